#include "ui/properties/task_area_fields.h"

#include "core/number_format.h"
#include "core/photometry/glare.h"
#include "core/photometry/lighting_standards.h"
#include "core/photometry/plan_rectangle.h"
#include "core/photometry/surrounding_zones.h"
#include "core/scene/scene_geometry.h"
#include "ui/disconnect_children.h"
#include "ui/properties/property_rows.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace lucerna {

namespace {
constexpr int kObserverColumns = 6;  // x, y, z, view x, view y, view z
constexpr int kNarrowLabelWidth = 230;  // px: a full-width note in a narrow properties dock

QString exact(double v) { return QString::fromStdString(shortestNumber(v)); }

// A number as typed, read in the C locale as the scene file writes it.
std::optional<double> parseNumber(const QString& text) {
    const std::string s = text.trimmed().toStdString();
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

// The value a field gives: the area's exact one while the field shows it unchanged.
double pick(const QDoubleSpinBox* field, double shown, double exactValue, double fromField) {
    return field->value() == shown ? exactValue : fromField;
}
}  // namespace

double taskAreaFloor(const Scene& scene) { return sceneBounds(scene).lo.y; }

QDoubleSpinBox* TaskAreaFields::makeSpin(const char* name, double lo, double hi, int decimals, const QString& suffix) {
    QDoubleSpinBox* spin = makePropertySpin(this, lo, hi, decimals);
    spin->setObjectName(name);
    spin->setSuffix(suffix);
    spin->setSingleStep(0.05);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, spin] {
        updateNotes();
        if (!filling_) emit edited(spin);
    });
    connect(spin, &QDoubleSpinBox::editingFinished, this, &TaskAreaFields::finished);
    return spin;
}

TaskAreaFields::TaskAreaFields(QWidget* parent) : QWidget(parent) {
    name_ = new QLineEdit(this);
    name_->setObjectName("taskAreaName");
    x_ = makeSpin("taskAreaX", -1e6, 1e6, 3, {});
    z_ = makeSpin("taskAreaZ", -1e6, 1e6, 3, {});
    width_ = makeSpin("taskAreaWidth", 0.01, 1e4, 3, tr(" m"));
    depth_ = makeSpin("taskAreaDepth", 0.01, 1e4, 3, tr(" m"));
    height_ = makeSpin("taskAreaHeight", -1e4, 1e4, 3, tr(" m"));
    rectangleNote_ = makeWrappingLabel(this, "taskAreaRectangleNote",
                                       tr("Not flat with its sides along x and z (on a wall or turned): the rectangle "
                                          "is kept as the scene file gives it."));
    activityArea_ = new QComboBox(this);
    activityArea_->setObjectName("taskAreaActivityArea");
    listAreas();
    activity_ = new QComboBox(this);
    activity_->setObjectName("taskAreaActivity");
    // Narrow enough for the properties dock: the lists' long names are read when opened.
    for (QComboBox* box : {activityArea_, activity_}) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(8);
        box->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    }
    requirement_ = makeWrappingLabel(this, "taskAreaRequirement");
    posture_ = new QComboBox(this);
    posture_->setObjectName("taskAreaPosture");
    posture_->addItem(tr("Seated"));
    posture_->addItem(tr("Standing"));
    posture_->setToolTip(tr("Where EN 12464-1:2021's cylindrical illuminance Ez is computed: 1.2 m above the floor "
                            "for seated work, 1.6 m for standing"));
    posture_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);  // as the activity's, for the dock
    posture_->setMinimumContentsLength(8);
    posture_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    spacing_ = makeSpin("taskAreaSpacing", 0, 100, 3, tr(" m"));
    spacing_->setToolTip(tr("The calculation grid's spacing; at its lowest, EN 12464-1's rule for the area's longer side"));
    surrounding_ = new QCheckBox(tr("Surrounding zone"), this);
    surrounding_->setObjectName("taskAreaSurrounding");
    surroundingWidth_ = makeSpin("taskAreaSurroundingWidth", 0.5, 1000, 2, tr(" m"));
    surroundingNote_ = makeWrappingLabel(this, "taskAreaSurroundingNote");
    background_ = new QCheckBox(tr("Background area"), this);
    background_->setObjectName("taskAreaBackground");
    backgroundWidth_ = makeSpin("taskAreaBackgroundWidth", 3, 1000, 2, tr(" m"));
    backgroundNote_ = makeWrappingLabel(this, "taskAreaBackgroundNote");
    observers_ = new QTableWidget(0, kObserverColumns, this);
    observers_->setObjectName("taskAreaObservers");
    observers_->setHorizontalHeaderLabels({tr("x"), tr("y"), tr("z"), tr("view x"), tr("view y"), tr("view z")});
    observers_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    observers_->verticalHeader()->setVisible(false);
    observers_->setMinimumHeight(90);
    observers_->setMaximumHeight(140);
    observers_->setToolTip(tr("Eye positions in the scene's unit and the directions they look in"));
    addObserver_ = new QPushButton(tr("Add"), this);
    addObserver_->setObjectName("taskAreaAddObserver");
    addObserver_->setToolTip(tr("Adds the next of the four default observers (mid-sides, eyes 1.2 m above the floor, "
                                "looking at the centre); edit its row"));
    removeObserver_ = new QPushButton(tr("Remove"), this);
    removeObserver_->setObjectName("taskAreaRemoveObserver");
    observersNote_ = makeWrappingLabel(this, "taskAreaObserversNote");

    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    // Short labels, wrapped above their fields where the dock is narrower still.
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    form->addRow(tr("Name"), name_);
    form->addRow(tr("Corner x"), x_);
    form->addRow(tr("Corner z"), z_);
    form->addRow(tr("Width (x)"), width_);
    form->addRow(tr("Depth (z)"), depth_);
    form->addRow(tr("Work plane"), height_);
    x_->setToolTip(tr("The corner of least x, in the scene's unit"));
    z_->setToolTip(tr("The corner of least z, in the scene's unit"));
    height_->setToolTip(tr("The work plane's height above the floor (the scene's lowest geometry)"));
    form->addRow(rectangleNote_);
    form->addRow(tr("Area"), activityArea_);
    form->addRow(tr("Activity"), activity_);
    form->addRow(requirement_);
    form->addRow(tr("Posture"), posture_);
    form->addRow(tr("Spacing"), spacing_);
    form->addRow(surrounding_, surroundingWidth_);
    form->addRow(surroundingNote_);
    form->addRow(background_, backgroundWidth_);
    form->addRow(backgroundNote_);
    auto* observerButtons = new QHBoxLayout;
    observerButtons->addWidget(addObserver_);
    observerButtons->addWidget(removeObserver_);
    observerButtons->addStretch(1);
    form->addRow(tr("Observers"), observerButtons);
    // Notes that change length keep room for two lines, so that none is squeezed over its neighbour.
    for (QLabel* note : {requirement_, surroundingNote_, backgroundNote_, observersNote_})
        note->setMinimumHeight(2 * note->fontMetrics().lineSpacing());
    // A 2021 requirement line runs to several lines: room from the start for the longest of either
    // edition at a narrow dock's width, since a dialog once shown does not grow for a longer one.
    requirementReserve_ = requirement_->minimumHeight();
    for (StandardEdition e : {StandardEdition::En12464_2011, StandardEdition::En12464_2021})
        for (const ActivityRequirement* r : activitiesOf(e))
            requirementReserve_ =
                std::max(requirementReserve_, requirement_->fontMetrics()
                                                  .boundingRect(QRect(0, 0, kNarrowLabelWidth, 100000), Qt::TextWordWrap,
                                                                QString::fromStdString(describeRequirement(*r, e)))
                                                  .height());
    form->addRow(observers_);
    form->addRow(observersNote_);

    connect(name_, &QLineEdit::editingFinished, this, [this] {
        if (!filling_ && name_->text() != shownName_) discreteEdit(name_);
    });
    connect(activityArea_, &QComboBox::activated, this, [this] {
        // The area the activity is already of: nothing changes (its list is shown).
        const QString area = activityArea_->currentIndex() == 0 ? QString() : activityArea_->currentText();
        const QString reference = activity_->isEnabled() ? activity_->currentData().toString() : QString();
        const ActivityRequirement* now = reference.isEmpty() ? nullptr : findActivity(reference.toStdString(), edition_);
        if ((now ? QString::fromUtf8(now->area) : QString()) == area) return;
        listActivities(area);
        updateNotes();
        discreteEdit(activity_);
    });
    connect(activity_, &QComboBox::activated, this, [this] {
        updateNotes();
        discreteEdit(activity_);
    });
    connect(posture_, &QComboBox::activated, this, [this] { discreteEdit(posture_); });
    for (QCheckBox* box : {surrounding_, background_})
        connect(box, &QCheckBox::toggled, this, [this, box] {
            updateNotes();
            if (!filling_) discreteEdit(box);
        });
    connect(observers_, &QTableWidget::itemChanged, this, [this] {
        updateNotes();
        if (!filling_) discreteEdit(observers_);
    });
    connect(addObserver_, &QPushButton::clicked, this, [this] {
        // The next of the default observers that the list lacks (the first again when it has them all).
        const TaskArea now = area();
        const std::vector<GlareObserver> defaults = defaultObservers(now, floorY_, metersPerUnit_);
        GlareObserver next = defaults.front();
        for (const GlareObserver& o : defaults)
            if (std::find(now.observers.begin(), now.observers.end(), o) == now.observers.end()) {
                next = o;
                break;
            }
        addObserverRow(next);
        updateNotes();
        discreteEdit(observers_);
    });
    connect(removeObserver_, &QPushButton::clicked, this, [this] {
        const int row = observers_->currentRow() >= 0 ? observers_->currentRow() : observers_->rowCount() - 1;
        if (row < 0) return;
        observers_->removeRow(row);
        updateNotes();
        discreteEdit(observers_);
    });
}

TaskAreaFields::~TaskAreaFields() { disconnectChildren(this); }

void TaskAreaFields::discreteEdit(const QObject* field) {
    emit finished();
    emit edited(field);
    emit finished();
}

void TaskAreaFields::listAreas() {
    const QSignalBlocker quiet(activityArea_);
    activityArea_->clear();
    activityArea_->addItem(tr("None"));
    for (const ActivityRequirement* a : activitiesOf(edition_))
        if (activityArea_->findText(QString::fromUtf8(a->area)) < 0) activityArea_->addItem(QString::fromUtf8(a->area));
}

void TaskAreaFields::listActivities(const QString& area) {
    activity_->clear();
    for (const ActivityRequirement* a : activitiesOf(edition_)) {
        if (QString::fromUtf8(a->area) != area) continue;
        // Under 2021, an activity its bundled table lacks is checked against the 2011 figures: say so.
        const QString fallback = a->edition != edition_ ? tr(" (2011)") : QString();
        activity_->addItem(QStringLiteral("%1 %2%3").arg(QString::fromUtf8(a->reference), QString::fromUtf8(a->activity), fallback),
                           QString::fromUtf8(a->reference));
    }
    activity_->setEnabled(activity_->count() > 0);
}

void TaskAreaFields::showActivity(const std::string& reference) {
    const ActivityRequirement* a = reference.empty() ? nullptr : findActivity(reference, edition_);
    activityArea_->setCurrentIndex(a ? activityArea_->findText(QString::fromUtf8(a->area)) : 0);
    listActivities(a ? QString::fromUtf8(a->area) : QString());
    if (a) activity_->setCurrentIndex(activity_->findData(QString::fromUtf8(a->reference)));
}

void TaskAreaFields::addObserverRow(const GlareObserver& o) {
    const int row = observers_->rowCount();
    observers_->insertRow(row);
    const double values[kObserverColumns] = {o.position.x, o.position.y, o.position.z, o.view.x, o.view.y, o.view.z};
    const QSignalBlocker quiet(observers_);
    for (int c = 0; c < kObserverColumns; ++c) observers_->setItem(row, c, new QTableWidgetItem(exact(values[c])));
}

void TaskAreaFields::setArea(const TaskArea& area, const Scene& scene) {
    filling_ = true;
    base_ = area;
    metersPerUnit_ = scene.metersPerUnit;
    floorY_ = taskAreaFloor(scene);
    if (lightingStandardOf(scene) != edition_) {
        edition_ = lightingStandardOf(scene);
        listAreas();
    }
    const std::optional<PlanRectangle> r = planRectangle(area.grid);
    rectangleEditable_ = r.has_value();
    for (QDoubleSpinBox* s : {x_, z_, width_, depth_, height_}) s->setEnabled(rectangleEditable_);
    rectangleNote_->setVisible(!rectangleEditable_);
    const QString unit = scene.metersPerUnit == 1 ? tr(" m") : QString();
    x_->setSuffix(unit);
    z_->setSuffix(unit);
    const PlanRectangle shownRect = r.value_or(PlanRectangle{area.grid.corner.x, area.grid.corner.z,
                                                             area.grid.edgeU.length(), area.grid.edgeV.length(),
                                                             area.grid.corner.y});
    x_->setValue(shownRect.x0);
    z_->setValue(shownRect.z0);
    width_->setValue(shownRect.width * metersPerUnit_);
    depth_->setValue(shownRect.depth * metersPerUnit_);
    height_->setValue((shownRect.y - floorY_) * metersPerUnit_);
    spacing_->setValue(area.grid.spacingMeters.value_or(0));
    {
        const QSignalBlocker quiet(surrounding_), quiet2(background_);
        surrounding_->setChecked(area.surroundingMeters.has_value());
        background_->setChecked(area.backgroundMeters.has_value());
    }
    surroundingWidth_->setValue(area.surroundingMeters.value_or(0.5));
    backgroundWidth_->setValue(area.backgroundMeters.value_or(3));
    shown_ = {x_->value(),       z_->value(),        width_->value(),           depth_->value(),
              height_->value(),  spacing_->value(),  surroundingWidth_->value(), backgroundWidth_->value()};
    name_->setText(QString::fromStdString(area.grid.name));
    shownName_ = QString::fromStdString(area.grid.name);
    showActivity(area.activity);
    posture_->setCurrentIndex(area.standing ? 1 : 0);
    {
        const QSignalBlocker quiet(observers_);
        observers_->setRowCount(0);
        for (const GlareObserver& o : area.observers) addObserverRow(o);
    }
    filling_ = false;
    updateNotes();
}

std::optional<std::vector<GlareObserver>> TaskAreaFields::observers(QString* why) const {
    std::vector<GlareObserver> list;
    for (int row = 0; row < observers_->rowCount(); ++row) {
        double v[kObserverColumns] = {};
        for (int c = 0; c < kObserverColumns; ++c) {
            const QTableWidgetItem* item = observers_->item(row, c);
            const std::optional<double> x = parseNumber(item ? item->text() : QString());
            if (!x) {
                if (why)
                    *why = tr("Observer %1: %2 is not a number").arg(row + 1).arg(observers_->horizontalHeaderItem(c)->text());
                return std::nullopt;
            }
            v[c] = *x;
        }
        GlareObserver o;
        o.position = V3d(v[0], v[1], v[2]);
        o.view = V3d(v[3], v[4], v[5]);
        if (!(o.view.length() > 0)) {
            if (why) *why = tr("Observer %1: the view direction must be non-zero").arg(row + 1);
            return std::nullopt;
        }
        list.push_back(o);
    }
    return list;
}

TaskArea TaskAreaFields::area() const {
    TaskArea a = base_;
    a.grid.name = name_->text().trimmed().toStdString();
    if (rectangleEditable_) {
        const PlanRectangle was = *planRectangle(base_.grid);
        PlanRectangle r;
        r.x0 = pick(x_, shown_.x, was.x0, x_->value());
        r.z0 = pick(z_, shown_.z, was.z0, z_->value());
        r.width = pick(width_, shown_.width, was.width, width_->value() / metersPerUnit_);
        r.depth = pick(depth_, shown_.depth, was.depth, depth_->value() / metersPerUnit_);
        r.y = pick(height_, shown_.height, was.y, floorY_ + height_->value() / metersPerUnit_);
        if (!(r == was)) a.grid = gridOfPlanRectangle(r, a.grid);
    }
    a.grid.spacingMeters = spacing_->value() == shown_.spacing ? base_.grid.spacingMeters
                           : spacing_->value() > 0           ? std::optional(spacing_->value())
                                                             : std::nullopt;
    a.activity = activity_->isEnabled() && activity_->currentIndex() >= 0 ? activity_->currentData().toString().toStdString()
                                                                          : std::string();
    const auto band = [](const QCheckBox* box, const QDoubleSpinBox* width, double shown, std::optional<double> was) {
        if (!box->isChecked()) return std::optional<double>();
        return std::optional(was && width->value() == shown ? *was : width->value());
    };
    a.surroundingMeters = band(surrounding_, surroundingWidth_, shown_.surrounding, base_.surroundingMeters);
    a.backgroundMeters = a.surroundingMeters ? band(background_, backgroundWidth_, shown_.background, base_.backgroundMeters)
                                             : std::nullopt;
    a.standing = posture_->currentIndex() == 1;
    a.observers = observers(nullptr).value_or(base_.observers);
    return a;
}

std::optional<QString> TaskAreaFields::problem() const {
    if (name_->text().trimmed().isEmpty()) return tr("The task area needs a name");
    QString why;
    if (!observers(&why)) return why;
    return std::nullopt;
}

void TaskAreaFields::updateNotes() {
    // The rule's spacing for the rectangle as it stands, shown where the field says "the rule".
    const double longer = std::max(width_->value(), depth_->value());
    spacing_->setSpecialValueText(tr("EN 12464-1: %1 m").arg(en12464Spacing(longer), 0, 'f', 2));
    const QString reference = activity_->isEnabled() ? activity_->currentData().toString() : QString();
    const ActivityRequirement* a = reference.isEmpty() ? nullptr : findActivity(reference.toStdString(), edition_);
    requirement_->setText(a ? QString::fromStdString(describeRequirement(*a, edition_))
                            : tr("No activity: nothing is checked."));
    // Room for this line at the width the label has once shown (a narrower dock than reserved for).
    requirement_->setMinimumHeight(
        std::max(requirementReserve_, requirement_->isVisible() ? requirement_->heightForWidth(requirement_->width()) : 0));
    requirement_->setToolTip(tr("Checked against %1 (File > Project Settings > Standard)")
                                 .arg(QString::fromUtf8(standardEditionName(edition_))));
    surroundingWidth_->setEnabled(surrounding_->isChecked());
    background_->setEnabled(surrounding_->isChecked());
    backgroundWidth_->setEnabled(surrounding_->isChecked() && background_->isChecked());
    if (a) {
        const ZoneRequirement s = surroundingZoneRequirement(a->maintainedLux);
        const ZoneRequirement b = backgroundAreaRequirement(s.maintainedLux);
        surroundingNote_->setText(tr("A band around the area (at least 0.5 m): Em %1 lx, U0 %2 (for a task of %3 lx)")
                                      .arg(s.maintainedLux, 0, 'f', 0)
                                      .arg(s.uniformity, 0, 'f', 2)
                                      .arg(a->maintainedLux, 0, 'f', 0));
        backgroundNote_->setText(tr("A band around that zone within the room (at least 3 m): Em %1 lx, U0 %2")
                                     .arg(b.maintainedLux, 0, 'f', 0)
                                     .arg(b.uniformity, 0, 'f', 2));
    } else {
        surroundingNote_->setText(tr("A band around the area (at least 0.5 m): its Em follows the activity's; U0 0.40"));
        backgroundNote_->setText(tr("A band around that zone within the room (at least 3 m): a third of its Em; U0 0.10"));
    }
    observersNote_->setText(observers_->rowCount() == 0
                                ? tr("None listed: UGR is checked from four observers at the sides' midpoints, "
                                     "eyes 1.2 m above the floor, looking at the centre.")
                                : tr("Positions in the scene's unit; views are directions."));
    removeObserver_->setEnabled(observers_->rowCount() > 0);
}

}  // namespace lucerna
