// GridPanel's widgets and their connections (its constructor); the rest is grid_panel.cpp.
#include "ui/calculation/grid_panel.h"

#include "ui/properties/number_fields.h"
#include "ui/calculation/ugr_table.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace lucerna {

namespace {
QDoubleSpinBox* lengthField(QWidget* parent, const char* name, double value, double lo, double hi, const QString& suffix) {
    return makeNumberField(parent, name, value, lo, hi, suffix, 2, 0.05);
}
}  // namespace

GridPanel::GridPanel(Document* doc, const YieldGate& gate, QWidget* parent) : QWidget(parent), doc_(doc), gate_(gate) {
    height_ = lengthField(this, "gridHeight", 0.8, -1000, 1000, tr(" m"));
    border_ = lengthField(this, "gridBorder", 0.5, 0, 1000, tr(" m"));
    spacing_ = lengthField(this, "gridSpacing", 0, 0, 1000, tr(" m"));
    spacing_->setSpecialValueText(tr("EN 12464-1"));  // 0: the standard's rule
    target_ = lengthField(this, "gridTarget", 2, 0.1, 50, tr(" %"));
    method_ = new QComboBox(this);
    method_->setObjectName("gridMethod");
    for (GridMethod m : kGridMethods) method_->addItem(QString::fromLatin1(gridMethodName(m)), int(m));
    method_->addItem(tr("auto"), kAutoMethod);
    method_->setItemData(method_->count() - 1, tr("bdpt where a lamp reaches points only through glass, else path"),
                         Qt::ToolTipRole);
    quantity_ = new QComboBox(this);
    quantity_->setObjectName("gridQuantity");
    quantity_->addItem(tr("Illuminance (lx)"));
    quantity_->addItem(tr("Daylight factor (%)"));
    quantity_->setItemData(1, tr("Under the CIE overcast sky alone, sun and electric lights off (SPEC.md section 5), "
                                 "with EN 17037's daylight provision"),
                           Qt::ToolTipRole);
    quantity_->addItem(tr("UGR (discomfort glare)"));
    quantity_->setItemData(kUgr, tr("An observer over each point at eye height, looking along the grid (CIE 117), "
                                    "for the new installation"),
                           Qt::ToolTipRole);
    cylindrical_ = new QCheckBox(tr("Cylindrical illuminance (Ez)"), this);
    cylindrical_->setObjectName("gridCylindrical");
    cylindrical_->setToolTip(tr("After the Em grid: the mean cylindrical illuminance over the task area at 1.2 m "
                                "above the floor (seated) or 1.6 m (standing), EN 12464-1:2021. Task areas only: "
                                "a drawn rectangle or the whole room has no posture"));
    roomSurfaces_ = new QCheckBox(tr("Walls and ceiling"), this);
    roomSurfaces_->setObjectName("gridRoomSurfaces");
    roomSurfaces_->setToolTip(tr("After the Em grid: the average illuminance of the walls and of the ceiling of the "
                                 "task area's room (else the scene's bounds), EN 12464-1:2021. Task areas only"));
    eyeHeight_ = new QComboBox(this);
    eyeHeight_->setObjectName("gridEyeHeight");
    eyeHeight_->addItem(tr("Seated, 1.2 m"), 1.2);
    eyeHeight_->addItem(tr("Standing, 1.7 m"), 1.7);
    viewAlong_ = new QComboBox(this);
    viewAlong_->setObjectName("gridView");
    viewAlong_->addItem(tr("+u (along the grid's first edge)"), int(GridViewDirection::PlusU));
    viewAlong_->addItem(tr("-u"), int(GridViewDirection::MinusU));
    viewAlong_->addItem(tr("+v (along its second edge)"), int(GridViewDirection::PlusV));
    viewAlong_->addItem(tr("-v"), int(GridViewDirection::MinusV));
    compute_ = new QPushButton(tr("Compute"), this);
    compute_->setObjectName("gridCompute");
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setObjectName("gridCancel");
    cancel_->setEnabled(false);
    export_ = new QPushButton(tr("Export CSV..."), this);
    export_->setObjectName("gridExport");
    export_->setEnabled(false);
    draw_ = new QPushButton(tr("Draw in viewport"), this);
    draw_->setObjectName("gridDraw");
    draw_->setToolTip(tr("Click two corners on a floor, a table or a wall in the viewport"));
    wholeRoom_ = new QPushButton(tr("Whole room"), this);
    wholeRoom_->setObjectName("gridWholeRoom");
    areaChoice_ = new QComboBox(this);
    areaChoice_->setObjectName("gridTaskArea");
    areaChoice_->setToolTip(tr("The scene's task areas: their own rectangle and spacing, and their activity's "
                               "requirements checked"));
    area_ = new QLabel(this);
    area_->setObjectName("gridArea");
    area_->setWordWrap(true);
    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1000);
    progress_->setTextVisible(false);
    figures_ = new QLabel(this);
    figures_->setObjectName("gridFigures");
    figures_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    figures_->setWordWrap(true);  // the glass warning is long: wrapped, not a wider dock
    status_ = new QLabel(this);
    status_->setObjectName("gridStatus");
    status_->setWordWrap(true);
    table_ = new QTableWidget(this);
    table_->setObjectName("gridTable");
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);

    auto* areaButtons = new QHBoxLayout;
    areaButtons->addWidget(draw_);
    areaButtons->addWidget(wholeRoom_);
    auto* form = new QFormLayout;
    form->addRow(tr("Task area"), areaChoice_);
    form->addRow(tr("Area"), area_);
    form->addRow(QString(), areaButtons);
    form->addRow(tr("Height above the surface"), height_);
    form->addRow(tr("Border (whole room)"), border_);
    form->addRow(tr("Spacing"), spacing_);
    form->addRow(tr("Error bar (95%)"), target_);
    form->addRow(tr("Estimator"), method_);
    form->addRow(tr("Quantity"), quantity_);
    auto* extras = new QVBoxLayout;
    extras->addWidget(cylindrical_);
    extras->addWidget(roomSurfaces_);
    form->addRow(tr("Also compute"), extras);
    form->addRow(tr("UGR observers' eyes"), eyeHeight_);
    form->addRow(tr("UGR observers look"), viewAlong_);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(compute_);
    buttons->addWidget(cancel_);
    buttons->addWidget(export_);
    // The figures (with a task area's extras and checks, thirty lines and more) scroll in their
    // own pane above the table of values, the two sharing what the dock leaves below the fields
    // at a divider the designer may drag: in one column the text pressed the table to a strip.
    auto* figuresScroll = new QScrollArea(this);
    figuresScroll->setObjectName("gridFiguresScroll");
    figuresScroll->setWidget(figures_);
    figuresScroll->setWidgetResizable(true);
    figuresScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // the lines wrap instead
    figuresScroll->setFrameShape(QFrame::NoFrame);
    figures_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    const int line = fontMetrics().lineSpacing();
    figuresScroll->setMinimumHeight(4 * line);
    // The header and three rows at least, so that the values never shrink to a strip.
    table_->setMinimumHeight(5 * (line + 8));
    auto* results = new QSplitter(Qt::Vertical, this);
    results->setObjectName("gridResults");
    results->setChildrenCollapsible(false);
    results->addWidget(figuresScroll);
    results->addWidget(table_);
    // The text three parts and the table two (a task area is a few rows): weights, scaled to the
    // height the splitter gets, each above its pane's minimum (a smaller one would be raised to it).
    results->setSizes({600, 400});
    // Its size hint is left out, so that a long text scrolls in its pane rather than making the
    // panel taller than the dock; its minimum still holds.
    results->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Ignored);
    results->setMinimumHeight(figuresScroll->minimumHeight() + table_->minimumHeight() + results->handleWidth());
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(buttons);
    layout->addWidget(progress_);
    layout->addWidget(status_);
    layout->addWidget(results, 1);

    connect(compute_, &QPushButton::clicked, this, &GridPanel::compute);
    connect(cancel_, &QPushButton::clicked, this, &GridPanel::cancel);
    connect(export_, &QPushButton::clicked, this, &GridPanel::exportClicked);
    connect(draw_, &QPushButton::clicked, this, &GridPanel::drawRequested);
    connect(wholeRoom_, &QPushButton::clicked, this, &GridPanel::useWholeRoom);
    useWholeRoom();
    connect(quantity_, &QComboBox::currentIndexChanged, this, &GridPanel::quantityChanged);
    quantityChanged();
    connect(doc_, &Document::changed, this, &GridPanel::sceneChanged);
    listTaskAreas();
    connect(doc_, &Document::changed, this, &GridPanel::listTaskAreas);
    connect(areaChoice_, &QComboBox::activated, this, &GridPanel::areaChosen);
    poll_.setInterval(100);
    connect(&poll_, &QTimer::timeout, this, &GridPanel::poll);
}

GridPanel::~GridPanel() { cancel(); }

}  // namespace lucerna
