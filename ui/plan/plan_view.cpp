#include "ui/plan/plan_view.h"

#include "core/photometry/lighting_standards.h"
#include "core/scene/scene_change.h"
#include "core/scene/scene_geometry.h"
#include "render/display/display.h"
#include "render/display/false_colour.h"
#include "render/display/iso_lines.h"
#include "ui/plan/plan_interaction.h"
#include "ui/plan/room_drawing.h"
#include "ui/plan/task_area_drawing.h"
#include "ui/plan/task_area_outlines.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QToolButton>
#include <QTransform>

#include <algorithm>
#include <cmath>
#include <map>

namespace lucerna {

namespace {
const QColor kBackground(246, 246, 242);
const QColor kWallColour(60, 60, 64);
}  // namespace

PlanView::PlanView(Document* doc, const YieldGate& gate, QWidget* parent)
    : QWidget(parent), doc_(doc), title_(new QLabel(this)), snap_(new QCheckBox(tr("Snap"), this)),
      snapStep_(new QDoubleSpinBox(this)), drawField_(new QToolButton(this)), scaleChoice_(new QComboBox(this)),
      labels_(new QAction(tr("Luminaire &Labels"), this)), interaction_(new PlanInteraction(this, doc, gate)),
      taskAreaDrawing_(new TaskAreaDrawing(this, doc)), taskAreaOutlines_(std::make_unique<TaskAreaOutlines>()),
      roomDrawing_(new RoomDrawing(this, doc)) {
    setMouseTracking(false);
    setFocusPolicy(Qt::ClickFocus);
    setAutoFillBackground(false);
    snap_->setObjectName("planSnap");
    snap_->setChecked(true);
    snap_->setToolTip(tr("Snap moved lights to a grid of this step"));
    snapStep_->setObjectName("planSnapStep");
    snapStep_->setRange(0.01, 10);
    snapStep_->setDecimals(2);
    snapStep_->setSingleStep(0.05);
    snapStep_->setValue(0.25);
    snapStep_->setSuffix(tr(" m"));
    auto* bar = new QHBoxLayout;
    bar->addWidget(title_);
    bar->addSpacing(16);
    bar->addWidget(snap_);
    bar->addWidget(snapStep_);
    bar->addSpacing(16);
    drawField_->setObjectName("planDrawField");
    drawField_->setText(tr("Draw Field"));
    drawField_->setCheckable(true);
    drawField_->setToolTip(tr("Drag a rectangle in the plan for a field of luminaires (Edit > Arrange Lights)"));
    bar->addWidget(drawField_);
    bar->addWidget(taskAreaDrawing_->button());
    bar->addWidget(roomDrawing_->button());
    bar->addSpacing(8);
    // The grid's legend: the plan's own scale (planScale), or the user's.
    scaleChoice_->setObjectName("planLegendScale");
    scaleChoice_->addItem(tr("Auto scale"));
    for (LegendScale s : {LegendScale::Linear, LegendScale::Logarithmic, LegendScale::Bands})
        scaleChoice_->addItem(legendScaleName(s), int(s));
    scaleChoice_->setToolTip(tr("The false-colour scale of the grid: the plan's own (linear, or logarithmic over a wide "
                                "range), linear, logarithmic, or bands between round values"));
    bar->addWidget(scaleChoice_);
    labels_->setObjectName("actionLuminaireLabels");
    labels_->setCheckable(true);
    labels_->setChecked(true);
    labels_->setToolTip(tr("Write the lights' names in the plan where they fit"));
    // The draw buttons and the scale's choice give way to a narrow plan (their text clipped)
    // rather than widen the window's central area past what the docks leave it.
    for (QToolButton* b : {drawField_, taskAreaDrawing_->button(), roomDrawing_->button()})
        b->setMinimumWidth(1);
    scaleChoice_->setMinimumWidth(1);
    bar->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(8, 6, 8, 6);
    layout->addLayout(bar);
    layout->addStretch(1);
    setProjection(Projection::Top);
    connect(drawField_, &QToolButton::toggled, this, [this](bool on) {
        if (on) emit message(tr("Drag the field's rectangle in the plan (Esc cancels)"));
        update();
    });
    // One drawing tool at a time.
    connect(drawField_, &QToolButton::toggled, this, [this](bool on) { if (on) taskAreaDrawing_->button()->setChecked(false); });
    connect(taskAreaDrawing_->button(), &QToolButton::toggled, this, [this](bool on) { if (on) drawField_->setChecked(false); });
    for (QToolButton* other : {drawField_, taskAreaDrawing_->button()}) {
        connect(other, &QToolButton::toggled, this, [this](bool on) { if (on) roomDrawing_->button()->setChecked(false); });
        connect(roomDrawing_->button(), &QToolButton::toggled, other, [other](bool on) { if (on) other->setChecked(false); });
    }
    connect(snap_, &QCheckBox::toggled, this, [this] { update(); });
    connect(labels_, &QAction::toggled, this, [this] { update(); });
    connect(scaleChoice_, &QComboBox::currentIndexChanged, this, [this] { update(); });
    connect(snapStep_, &QDoubleSpinBox::valueChanged, this, [this] { update(); });
    connect(doc_, &Document::changed, this, [this] { update(); });
    connect(doc_, &Document::replaced, this, [this] {
        fitted_ = false;
        result_.reset();
        gridScale_ = {};
        selected_ = -1;
        selectedSet_.clear();
        selectedCount_ = 0;
        selectedTaskArea_ = -1;
    });
}

PlanView::~PlanView() = default;

void PlanView::setProjection(Projection projection) {
    projection_ = projection;
    fitted_ = false;
    title_->setText(projection == Projection::Top     ? tr("Plan")
                    : projection == Projection::Front ? tr("Front elevation")
                                                      : tr("Side elevation"));
    title_->setToolTip(projection == Projection::Top     ? tr("Seen from above: x to the right, z down")
                       : projection == Projection::Front ? tr("Seen from +z, looking along -z: x to the right, y up")
                                                         : tr("Seen from +x, looking along -x: z to the left, y up"));
    title_->setMinimumWidth(title_->fontMetrics().horizontalAdvance(tr("Front elevation")) + 8);
    // A field lies on the ceiling: it is drawn in the plan only.
    drawField_->setEnabled(projection == Projection::Top);
    if (projection != Projection::Top) drawField_->setChecked(false);
    taskAreaDrawing_->projectionChanged();
    roomDrawing_->projectionChanged();
    update();
}

void PlanView::setSelectedLights(const std::vector<int>& lights) {
    selectedSet_.assign(doc_->scene().lights.size(), 0);
    selectedCount_ = 0;
    for (int i : lights)
        if (i >= 0 && size_t(i) < selectedSet_.size()) selectedSet_[size_t(i)] = 1, ++selectedCount_;
    update();
}

void PlanView::setSelectedTaskArea(int index) {
    selectedTaskArea_ = index;
    update();
}

QToolButton* PlanView::drawTaskAreaButton() const { return taskAreaDrawing_->button(); }

void PlanView::setDrawingField(bool on) { drawField_->setChecked(on && projection_ == Projection::Top); }

void PlanView::setSelectedLight(int index) {
    selected_ = index;
    update();
}

void PlanView::setGridResult(const CalculationGrid& grid, const GridLayout& layout, std::shared_ptr<const GridResult> result,
                             const QString& unit) {
    gridUnit_ = unit;
    grid_ = grid;
    layout_ = layout;
    result_ = std::move(result);
    resultScene_ = doc_->snapshot();
    gridScale_ = {};
    gridStatistics_ = {};
    if (result_ && !result_->lux.empty()) gridStatistics_ = gridStatistics(result_->lux), gridScale_ = planScale(gridStatistics_);
    update();
}

double PlanView::snapMeters() const { return snap_->isChecked() ? snapStep_->value() : 0.0; }

void PlanView::setSnapMeters(double meters) {
    snap_->setChecked(meters > 0);
    if (meters > 0) snapStep_->setValue(meters);
}

QColor PlanView::lightColour() { return QColor(230, 120, 0); }
QColor PlanView::selectionColour() { return QColor(30, 110, 230); }
QColor PlanView::isoLineColour() { return QColor(0, 0, 0); }
QColor PlanView::cameraColour() { return QColor(140, 40, 200); }

// ---- projection ----

QPointF PlanView::widgetOfPlan(const QPointF& plan) const { return offset_ + plan * scale_; }
QPointF PlanView::planOfWidget(const QPointF& widget) const { return (widget - offset_) / scale_; }
QPointF PlanView::widgetOf(const V3d& world) const { return widgetOfPlan(planPoint(projection_, world)); }
QTransform PlanView::planToWidget() const { return QTransform(scale_, 0, 0, scale_, offset_.x(), offset_.y()); }

void PlanView::panBy(const QPointF& pixels) {
    offset_ += pixels;
    fitted_ = true;
    update();
}

void PlanView::zoomAbout(const QPointF& widget, double factor) {
    const QPointF plan = planOfWidget(widget);
    scale_ *= factor;
    offset_ = widget - plan * scale_;
    fitted_ = true;
    update();
}

std::optional<QPointF> PlanView::lightSymbol(int index) const {
    const auto& lights = doc_->scene().lights;
    if (index < 0 || size_t(index) >= lights.size() || lights[size_t(index)].type == LightType::Directional ||
        lights[size_t(index)].type == LightType::Sun)
        return std::nullopt;
    return widgetOf(lights[size_t(index)].position);
}

std::optional<Legend> PlanView::gridLegend() const {
    if (!result_ || result_->lux.empty() || layout_.points.size() != result_->lux.size()) return std::nullopt;
    const V3d axis = projection_ == Projection::Top ? V3d(0, 1, 0) : projection_ == Projection::Front ? V3d(0, 0, 1) : V3d(1, 0, 0);
    if (std::abs(grid_.normal().dot(axis)) < 0.9) return std::nullopt;  // the grid is not on a plane of this view
    // A task area's grid (the grid dock's grid is the area's own) whose activity states Em: the
    // colours centre on it, as the report's plan of the area does.
    std::optional<double> required;
    const Scene& scene = doc_->scene();
    for (const TaskArea& t : scene.taskAreas)
        if (gridUnit_.isEmpty() && t.grid.name == grid_.name && t.grid.corner == grid_.corner && !t.activity.empty()) {
            if (const ActivityRequirement* a = findActivity(t.activity, lightingStandardOf(scene))) required = a->maintainedLux;
            break;
        }
    PlanScale scale = required ? requirementScale(*required, gridStatistics_) : gridScale_;
    // Chosen logarithmic, a requirement's scale runs over the same factors either side of Em.
    if (required && !scale.logScale && legendScale() == LegendScale::Logarithmic) scale.lo = *required / 5, scale.hi = *required * 5;
    Legend legend = scale.legend(gridUnit_.isEmpty() ? tr("lx") : gridUnit_, legendScale());
    if (required) {
        legend.target = *required;
        legend.targetLabel = tr("Em %1").arg(tickText(*required));
    }
    return legend;
}

void PlanView::setLegendScale(std::optional<LegendScale> scale) {
    scaleChoice_->setCurrentIndex(scale ? scaleChoice_->findData(int(*scale)) : 0);
}

std::optional<LegendScale> PlanView::legendScale() const {
    if (scaleChoice_->currentIndex() <= 0) return std::nullopt;
    return LegendScale(scaleChoice_->currentData().toInt());
}

bool PlanView::gridOutOfDate() const {
    if (!result_ || !resultScene_) return false;
    return diff(*resultScene_, doc_->scene()).changesIlluminance();
}

void PlanView::fitToScene() {
    const Scene& scene = doc_->scene();
    const SceneBounds b = sceneBounds(scene);
    double u0 = 1e300, u1 = -1e300, w0 = 1e300, w1 = -1e300;
    for (int k = 0; k < 8; ++k) {
        const QPointF p = planPoint(projection_, V3d(k & 1 ? b.hi.x : b.lo.x, k & 2 ? b.hi.y : b.lo.y, k & 4 ? b.hi.z : b.lo.z));
        u0 = std::min(u0, p.x()), u1 = std::max(u1, p.x()), w0 = std::min(w0, p.y()), w1 = std::max(w1, p.y());
    }
    const double du = std::max(u1 - u0, 1e-9), dw = std::max(w1 - w0, 1e-9);
    const double top = 40;  // the bar's band
    const double availW = std::max(width() - 140.0, 50.0), availH = std::max(height() - top - 30.0, 50.0);
    scale_ = std::min(availW / du, availH / dw);
    const QPointF centre((u0 + u1) / 2, (w0 + w1) / 2);
    offset_ = QPointF(20 + availW / 2, top + availH / 2) - centre * scale_;
    fitted_ = true;
    update();
}

// ---- geometry ----

const std::vector<PlanFace>& PlanView::faces() {
    const SceneSnapshot scene = doc_->snapshot();
    if (facesScene_ && facesProjection_ == projection_) {
        const SceneChange change = facesScene_ == scene ? SceneChange{} : diff(*facesScene_, *scene);
        if (!change.geometry && !change.materials) return faces_;
    }
    facesScene_ = scene;
    facesProjection_ = projection_;
    faces_ = planFaces(*scene, projection_, PlanShading::Tint);
    return faces_;
}

void PlanView::paintSnapGrid(QPainter& painter) const {
    const double step = snapMeters() / doc_->scene().metersPerUnit;  // scene units
    if (step <= 0 || step * scale_ < 8) return;  // too dense to help
    painter.setPen(QPen(QColor(0, 0, 0, 22), 0));
    const QPointF lo = planOfWidget(QPointF(0, 0)), hi = planOfWidget(QPointF(width(), height()));
    for (double u = std::ceil(lo.x() / step) * step; u <= hi.x(); u += step) {
        const double x = widgetOfPlan(QPointF(u, 0)).x();
        painter.drawLine(QPointF(x, 0), QPointF(x, height()));
    }
    for (double w = std::ceil(lo.y() / step) * step; w <= hi.y(); w += step) {
        const double y = widgetOfPlan(QPointF(0, w)).y();
        painter.drawLine(QPointF(0, y), QPointF(width(), y));
    }
}

void PlanView::paintCalculationGrid(QPainter& painter) const {
    const std::optional<Legend> legend = gridLegend();
    if (!legend) return;
    const int nu = layout_.nu, nv = layout_.nv;
    const V3d du = grid_.edgeU / nu, dv = grid_.edgeV / nv;  // one cell, scene units
    // Cells: each point's value over its cell.
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const size_t k = size_t(j) * size_t(nu) + size_t(i);
            const V3d c = layout_.points[k];
            const QPointF p[4] = {widgetOf(c - du * 0.5 - dv * 0.5), widgetOf(c + du * 0.5 - dv * 0.5),
                                  widgetOf(c + du * 0.5 + dv * 0.5), widgetOf(c - du * 0.5 + dv * 0.5)};
            const QColor colour = legendColour(*legend, result_->lux[k]);
            painter.setPen(QPen(colour, 0));
            painter.setBrush(colour);
            painter.drawConvexPolygon(p, 4);
        }
    // Iso-lux lines between the points, each level labelled once on its longest piece.
    const V3d origin = layout_.points[0];
    const auto lattice = [&](double i, double j) { return widgetOf(origin + du * i + dv * j); };
    const std::vector<double>& levels = gridScale_.levels;
    const std::vector<IsoSegment> segments = isoSegments(result_->lux, nu, nv, levels);
    painter.setPen(QPen(isoLineColour(), 1.5));
    std::vector<std::pair<double, QPointF>> labelAt(levels.size(), {-1.0, QPointF()});
    for (const IsoSegment& s : segments) {
        const QPointF a = lattice(s.i0, s.j0), b = lattice(s.i1, s.j1);
        painter.drawLine(a, b);
        const size_t li = size_t(std::find(levels.begin(), levels.end(), s.level) - levels.begin());
        const double len = QLineF(a, b).length();
        if (li < labelAt.size() && len > labelAt[li].first) labelAt[li] = {len, (a + b) / 2};
    }
    QFont small = painter.font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.85));
    painter.setFont(small);
    for (size_t li = 0; li < levels.size(); ++li) {
        if (labelAt[li].first < 0) continue;
        const QString text = QString::number(levels[li], 'g', 6);
        const QRectF box = painter.fontMetrics().boundingRect(text).adjusted(-2, 0, 2, 0);
        const QRectF at(labelAt[li].second - QPointF(box.width() / 2, box.height() / 2), box.size());
        painter.fillRect(at, QColor(255, 255, 255, 210));
        painter.drawText(at, Qt::AlignCenter, text);
    }
    painter.setFont(font());
    if (gridOutOfDate()) {
        const QString text = tr("Grid out of date (the scene changed): compute it again.");
        const double lineHeight = painter.fontMetrics().height();
        const QRectF band(0, height() - 3 * lineHeight - 34, width(), 2 * lineHeight + 8);
        painter.fillRect(band, QColor(255, 236, 170));
        painter.setPen(Qt::black);
        painter.drawText(band.adjusted(6, 0, -6, 0), Qt::AlignCenter | Qt::TextWordWrap, text);
    }
}

void PlanView::paintField(QPainter& painter) const {
    const std::optional<QRectF> field = interaction_->fieldBeingDrawn();
    if (!field) return;
    const QRectF r(widgetOfPlan(field->topLeft()), widgetOfPlan(field->bottomRight()));
    painter.setPen(QPen(selectionColour(), 1.5, Qt::DashLine));
    QColor fill(30, 110, 230, 30);
    painter.setBrush(fill);
    painter.drawRect(r);
    const double mpu = doc_->scene().metersPerUnit;
    const QString size = tr("%1 x %2 m")
                             .arg(field->width() * mpu, 0, 'g', 4)
                             .arg(field->height() * mpu, 0, 'g', 4);
    painter.setPen(Qt::black);
    painter.drawText(r.bottomRight() + QPointF(6, 14), size);
}

void PlanView::paintCamera(QPainter& painter) const {
    // The scene camera as a dot with its field of view opening toward the target, so that a
    // camera outside the walls, or looking at one, is seen at once.
    const Camera& c = doc_->scene().camera;
    const QPointF at = widgetOf(c.position), toward = widgetOf(c.target) - at;
    const double len = std::hypot(toward.x(), toward.y());
    painter.setPen(QPen(cameraColour(), 2));
    painter.setBrush(cameraColour());
    painter.drawEllipse(at, 4, 4);
    if (len < 2) return;  // looking straight along the view's axis
    const double angle = std::atan2(toward.y(), toward.x());
    const double half = std::atan(std::tan(c.fovYDeg * M_PI / 360) * double(c.width) / std::max(c.height, 1));  // horizontal
    const double reach = 40;
    QPolygonF cone;
    cone << at << at + reach * QPointF(std::cos(angle - half), std::sin(angle - half))
         << at + reach * QPointF(std::cos(angle + half), std::sin(angle + half));
    QColor fill = cameraColour();
    fill.setAlpha(50);
    painter.setBrush(fill);
    painter.drawPolygon(cone);
}

void PlanView::paintScaleBar(QPainter& painter) const {
    // A bar of a round length in metres, at most a fifth of the width.
    const double mpu = doc_->scene().metersPerUnit;
    const double pxPerMeter = scale_ / mpu;
    const double meters = scaleBarMeters(pxPerMeter, width() / 5.0);
    if (meters <= 0) return;
    const double len = meters * pxPerMeter;
    const QPointF a(16, height() - 16), b(16 + len, height() - 16);
    painter.setPen(QPen(Qt::black, 2));
    painter.drawLine(a, b);
    painter.drawLine(a, a - QPointF(0, 5));
    painter.drawLine(b, b - QPointF(0, 5));
    painter.drawText(QPointF(b.x() + 6, b.y() + 4), tr("%1 m").arg(meters, 0, 'g', 6));
}

void PlanView::paintEvent(QPaintEvent*) {
    if (!fitted_) fitToScene();
    QPainter painter(this);
    painter.fillRect(rect(), kBackground);
    painter.setRenderHint(QPainter::Antialiasing, true);
    paintSnapGrid(painter);
    const QTransform toWidget = planToWidget();
    paintPlanFills(painter, faces(), toWidget, rect(), 0);
    paintCalculationGrid(painter);
    // Walls and furniture sides stay visible over the grid.
    paintPlanWalls(painter, faces_, toWidget, QPen(kWallColour, 1.6), QPen(kWallColour, 1.6));
    roomDrawing_->paintRooms(painter);
    if (projection_ == Projection::Top)
        taskAreaOutlines_->paint(painter, doc_->snapshot(), [this](const V3d& p) { return widgetOf(p); }, selectedTaskArea_);
    paintCamera(painter);
    lightTypes_ = planLightTypes(doc_->scene());
    paintLights(painter);
    const std::vector<QRectF> captions = paintGroups(painter);
    layOutLegends(font());
    paintLabels(painter, captions);
    paintField(painter);
    taskAreaDrawing_->paint(painter);
    roomDrawing_->paint(painter);
    paintScaleBar(painter);
    paintLegends(painter);  // last: nothing covers them
}

void PlanView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    fitted_ = false;
}

}  // namespace lucerna
