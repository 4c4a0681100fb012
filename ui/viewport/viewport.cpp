#include "ui/viewport/viewport.h"

#include "core/photometry/calculation_grid.h"
#include "ui/viewport/camera_navigation.h"
#include "ui/commands/light_commands.h"
#include "ui/commands/scene_commands.h"
#include "ui/viewport/light_pick.h"
#include "ui/viewport/light_placement.h"
#include "ui/viewport/light_symbols.h"

#include <QAction>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {
QString nameOf(const Light& light) { return QString::fromStdString(light.name); }
}  // namespace

int nextMergeKey() {
    // Above the small fixed keys the property panel uses for its fields.
    static int key = 1 << 20;
    return ++key;
}

Viewport::Viewport(Document* doc, const YieldGate& gate, QWidget* parent)
    : ImageView(parent), doc_(doc), gate_(gate) {
    showNoFrame();
    // Tracking shows which gizmo handle a drag would take, and where a tool would act.
    setMouseTracking(true);
    setFocusPolicy(Qt::ClickFocus);
    connect(doc_, &Document::changed, this, [this] {
        aim_->setEnabled(aimable(selected_));
        update();
    });

    const auto action = [this](const QString& text, const char* name, const QString& key, Tool tool) {
        auto* a = new QAction(text, this);
        a->setObjectName(name);
        a->setShortcut(QKeySequence(key));
        a->setCheckable(true);
        connect(a, &QAction::triggered, this, [this, tool] { setTool(tool_ == tool ? Tool::Navigate : tool); });
        return a;
    };
    placePoint_ = action(tr("Place P&oint Light on a Surface"), "actionPlacePointLight", tr("Ctrl+Shift+P"),
                         Tool::PlacePoint);
    placeSpot_ = action(tr("Place Spot &Light on a Surface"), "actionPlaceSpotLight", tr("Ctrl+Shift+L"),
                        Tool::PlaceSpot);
    aim_ = action(tr("&Aim Selected Light at a Surface"), "actionAimLight", tr("Ctrl+Shift+A"), Tool::Aim);
    aim_->setEnabled(false);
    drawGrid_ = action(tr("Draw &Calculation Grid Rectangle"), "actionDrawGrid", tr("Ctrl+Shift+G"), Tool::GridRectangle);
}

Viewport::~Viewport() = default;

QList<QAction*> Viewport::toolActions() const { return {placePoint_, placeSpot_, aim_, drawGrid_}; }

ViewMapping Viewport::mapping() const { return ViewMapping(doc_->scene().camera, imageRect()); }

void Viewport::showNoFrame(const QString& error) {
    setPlaceholder(error.isEmpty() ? tr("Preparing the live preview...") : tr("Live preview failed: %1").arg(error));
    setImage({});
}

void Viewport::setSelectedLight(int index) {
    selected_ = index;
    aim_->setEnabled(aimable(index));
    if (tool_ == Tool::Aim && !aimable(index)) setTool(Tool::Navigate);
    update();
}

void Viewport::setSelectedLights(const std::vector<int>& lights) {
    selectedLights_ = QSet<int>(lights.begin(), lights.end());
    update();
}

void Viewport::setSelectedObject(int index) {
    selectedObject_ = index;
    update();
}

bool Viewport::aimable(int light) const {
    const Scene& scene = doc_->scene();
    return light >= 0 && light < int(scene.lights.size()) && scene.lights[size_t(light)].type != LightType::Point;
}

bool Viewport::setTool(Tool tool) {
    const Tool requested = tool;
    if (tool == Tool::Aim && !aimable(selected_)) {
        emit message(tr("Select a spot, luminaire or directional light to aim."));
        tool = Tool::Navigate;
    }
    const bool changed = tool != tool_;
    tool_ = tool;
    placePoint_->setChecked(tool == Tool::PlacePoint);
    placeSpot_->setChecked(tool == Tool::PlaceSpot);
    aim_->setChecked(tool == Tool::Aim);
    drawGrid_->setChecked(tool == Tool::GridRectangle);
    gridCorner_.reset();
    setCursor(tool == Tool::Navigate ? Qt::ArrowCursor : Qt::CrossCursor);
    hover_.reset();
    if (tool != Tool::Navigate) setFocus(Qt::OtherFocusReason);  // for Escape
    if (changed) emit toolChanged(tool);
    update();
    return tool_ == requested;
}

const SurfacePicker* Viewport::picker() const {
    const Scene& scene = doc_->scene();
    if (!picker_ || !picker_->sameGeometry(scene)) {
        picker_.reset();
        try {
            picker_ = std::make_unique<SurfacePicker>(scene);
            pickerFailed_ = false;
        } catch (const std::exception&) {
            pickerFailed_ = true;  // placeAt() says so in the status bar
        }
    }
    return picker_.get();
}

std::optional<SurfaceHit> Viewport::surfaceAt(const QPointF& widget) const {
    const ViewMapping view = mapping();
    if (!view.isValid() || !imageRect().contains(widget)) return std::nullopt;
    const SurfacePicker* surfaces = picker();
    if (!surfaces) return std::nullopt;
    const QPointF r = view.toRaster(widget);
    return surfaces->pick(doc_->scene().camera, r.x(), r.y());
}

std::optional<QPointF> Viewport::lightMarker(int index) const {
    const Scene& scene = doc_->scene();
    if (index < 0 || index >= int(scene.lights.size())) return std::nullopt;
    // Picked where drawn (viewport_painting.cpp); the selected light's symbol has the same centre.
    const auto symbol = lightSymbol(scene.lights[size_t(index)], mapping(), scene.metersPerUnit);
    return symbol ? std::optional(symbol->centre) : std::nullopt;
}

std::optional<LightGizmo> Viewport::gizmo() const {
    const Scene& scene = doc_->scene();
    if (selected_ < 0 || selected_ >= int(scene.lights.size()) || !lightMarker(selected_)) return std::nullopt;
    return LightGizmo::of(scene.lights[size_t(selected_)], mapping());
}

int Viewport::lightAt(const QPointF& pos) const {
    // The selected light wins a tie: it is the one being worked on.
    return lightNear(int(doc_->scene().lights.size()), [this](int i) { return lightMarker(i); }, pos, 10.0, selected_);
}

// ---- mouse ----

void Viewport::mousePressEvent(QMouseEvent* event) {
    if (drag_ != Drag::None) return;
    const QPointF pos = event->position();
    pressed_ = last_ = pos;
    mergeKey_ = nextMergeKey();
    wheelKey_ = nextMergeKey();
    if (event->button() == Qt::LeftButton) {
        if (tool_ == Tool::PlacePoint || tool_ == Tool::PlaceSpot) return placeAt(pos);
        if (tool_ == Tool::GridRectangle) return gridCornerAt(pos);
        if (tool_ == Tool::Aim || (event->modifiers() & Qt::ControlModifier)) return aimAt(pos);
        dragLight_ = lightAt(pos);
        const auto g = gizmo();
        const GizmoHandle handle = g ? g->handleAt(pos) : GizmoHandle::None;
        if (handle != GizmoHandle::None && dragLight_ != selected_) {
            drag_ = handle == GizmoHandle::Aim ? Drag::Aim : Drag::Axis;
            dragHandle_ = handle;
            dragLight_ = selected_;
            dragStart_ = doc_->scene().lights[size_t(selected_)];
            aimTipStart_ = dragStart_.position + dragStart_.direction.normalized() * g->aimLength;
        } else if (dragLight_ >= 0) {
            emit lightClicked(dragLight_);
            drag_ = Drag::MoveLight;
        } else {
            drag_ = Drag::Pending;
        }
    } else if (event->button() == Qt::RightButton || event->button() == Qt::MiddleButton) {
        drag_ = Drag::Pan;
    }
    // The preview comes first on the cores while the user interacts.
    if (drag_ != Drag::None) hold_ = std::make_unique<YieldGate::Scope>(gate_.counter());
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QPointF pos = event->position();
    if (drag_ == Drag::None) {
        // Hover: which handle a press would take, where a tool would act.
        const auto g = gizmo();
        const GizmoHandle handle = g && tool_ == Tool::Navigate && lightAt(pos) != selected_ ? g->handleAt(pos)
                                                                                               : GizmoHandle::None;
        if (tool_ != Tool::Navigate) hover_ = surfaceAt(pos);
        if (handle != hoverHandle_ || tool_ != Tool::Navigate) {
            hoverHandle_ = handle;
            update();
        }
        return;
    }
    const QRectF r = imageRect();
    if (r.isEmpty()) return;
    if (drag_ == Drag::Pending) {
        if (std::hypot(pos.x() - pressed_.x(), pos.y() - pressed_.y()) < kClickSlop) return;
        drag_ = Drag::Orbit;  // last_ is still the press: the orbit covers the whole way
    }
    const QPointF delta = pos - last_;
    last_ = pos;
    if (delta.isNull()) return;
    const Scene& scene = doc_->scene();
    const double fx = delta.x() / r.height(), fy = delta.y() / r.height();  // fractions of the view's height
    switch (drag_) {
    case Drag::Orbit:
        doc_->undoStack()->push(new EditCameraCommand(
            doc_, orbitCamera(scene.camera, fx * 3.0, fy * 3.0), mergeKey_, tr("Orbit")));
        break;
    case Drag::Pan:
        doc_->undoStack()->push(new EditCameraCommand(doc_, panCamera(scene.camera, fx, -fy), mergeKey_, tr("Pan")));
        break;
    case Drag::MoveLight: {
        if (dragLight_ < 0 || dragLight_ >= int(scene.lights.size())) break;
        const Camera& c = scene.camera;
        Light light = scene.lights[size_t(dragLight_)];
        const V3d f = (c.target - c.position).normalized();
        const V3d right = f.cross(c.up).normalized(), up = right.cross(f);
        // World size of one view height at the light's depth: the light follows the mouse.
        const double depth = std::max((light.position - c.position).dot(f), 1e-6);
        const double height = 2 * depth * std::tan(radians(c.fovYDeg) / 2);
        light.position += (right * fx - up * fy) * height;
        doc_->undoStack()->push(new EditLightCommand(doc_, dragLight_, light, mergeKey_, tr("Move %1").arg(nameOf(light))));
        break;
    }
    case Drag::Axis: {
        if (dragLight_ < 0 || dragLight_ >= int(scene.lights.size())) break;
        const int axis = int(dragHandle_) - int(GizmoHandle::X);
        const V3d direction(axis == 0, axis == 1, axis == 2);
        Light light = scene.lights[size_t(dragLight_)];
        // From the drag's start each time, so that no rounding piles up along the way.
        light.position = dragAlongAxis(mapping(), dragStart_.position, direction, pressed_, pos);
        // The other two coordinates exactly as they were.
        for (int k = 0; k < 3; ++k)
            if (k != axis) light.position[k] = dragStart_.position[k];
        doc_->undoStack()->push(new EditLightCommand(
            doc_, dragLight_, light, mergeKey_, tr("Move %1 along %2").arg(nameOf(light), QString(QChar(char16_t(u'x' + axis))))));
        break;
    }
    case Drag::Aim: {
        if (dragLight_ < 0 || dragLight_ >= int(scene.lights.size())) break;
        Light light = scene.lights[size_t(dragLight_)];
        if (const auto d = aimThroughPlane(mapping(), light.position, aimTipStart_, pos)) {
            light.direction = *d;
            doc_->undoStack()->push(new EditLightCommand(doc_, dragLight_, light, mergeKey_, tr("Aim %1").arg(nameOf(light))));
        }
        break;
    }
    case Drag::Pending:
    case Drag::None: break;
    }
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (drag_ == Drag::Pending && event->button() == Qt::LeftButton) selectAt(event->position());
    endDrag();
}

void Viewport::leaveEvent(QEvent*) {
    if (!hover_ && hoverHandle_ == GizmoHandle::None) return;
    hover_.reset();
    hoverHandle_ = GizmoHandle::None;
    update();
}

void Viewport::endDrag() {
    drag_ = Drag::None;
    dragLight_ = -1;
    dragHandle_ = GizmoHandle::None;
    hold_.reset();
    update();
}

void Viewport::placeAt(const QPointF& pos) {
    const auto hit = surfaceAt(pos);
    if (!hit) {
        emit message(pickerFailed_ ? tr("Surfaces cannot be picked: the ray tracer could not start.")
                                   : tr("No surface there to place the light on: click a surface."));
        return;
    }
    const LightType type = tool_ == Tool::PlaceSpot ? LightType::Spot : LightType::Point;
    const Scene& scene = doc_->scene();
    const double offset = placementOffset(scene.metersPerUnit, picker_->diagonal());
    const Light light = placedLight(scene, type, doc_->uniqueName(type == LightType::Spot ? "spot" : "point"), *hit, offset);
    const int index = int(scene.lights.size());
    const QString on = QString::fromStdString(scene.objects[size_t(hit->object)].name);
    // `scene` is gone once the command has replaced the document's scene.
    doc_->undoStack()->push(new AddLightCommand(doc_, index, light, tr("Place %1").arg(nameOf(light))));
    setTool(Tool::Navigate);
    emit lightPlaced(index);
    emit message(tr("Placed %1 on %2").arg(nameOf(light), on));
}

void Viewport::aimAt(const QPointF& pos) {
    if (!aimable(selected_)) {
        emit message(tr("Select a spot, luminaire or directional light to aim."));
        return;
    }
    const auto hit = surfaceAt(pos);
    const std::optional<Light> aimed = hit ? aimedLight(doc_->scene().lights[size_t(selected_)], *hit) : std::nullopt;
    if (!aimed) {
        emit message(hit ? tr("The light sits on that point: click another.") : tr("No surface there to aim at: click a surface."));
        return;
    }
    doc_->undoStack()->push(new EditLightCommand(doc_, selected_, *aimed, 0, tr("Aim %1").arg(nameOf(*aimed))));
    setTool(Tool::Navigate);
}

void Viewport::gridCornerAt(const QPointF& pos) {
    const auto hit = surfaceAt(pos);
    if (!hit) {
        emit message(tr("No surface there for the grid: click a floor, a table or a wall."));
        return;
    }
    if (!gridCorner_) {
        gridCorner_ = hit;
        update();
        return;
    }
    const SurfaceHit first = *gridCorner_;
    setTool(Tool::Navigate);
    emit gridRectangleDrawn(first.point, first.normal, hit->point);
}

void Viewport::selectAt(const QPointF& pos) {
    const auto hit = surfaceAt(pos);
    emit objectClicked(hit ? hit->object : -1);
}

void Viewport::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0) return;
    // Successive wheel steps merge until some other interaction takes a new key.
    if (drag_ != Drag::None) return;
    doc_->undoStack()->push(
        new EditCameraCommand(doc_, dollyCamera(doc_->scene().camera, std::pow(0.85, steps)), wheelKey_, tr("Zoom")));
}

// ---- keyboard ----

void Viewport::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && tool_ != Tool::Navigate) {
        setTool(Tool::Navigate);
        emit message(tr("Cancelled"));
        return;
    }
    // Keys with Ctrl, Alt or Meta belong to shortcuts, not to flying.
    if (event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)) {
        ImageView::keyPressEvent(event);
        return;
    }
    // right, up, forward
    double r = 0, u = 0, f = 0;
    switch (event->key()) {
    case Qt::Key_W: case Qt::Key_Up: f = 1; break;
    case Qt::Key_S: case Qt::Key_Down: f = -1; break;
    case Qt::Key_D: case Qt::Key_Right: r = 1; break;
    case Qt::Key_A: case Qt::Key_Left: r = -1; break;
    case Qt::Key_E: u = 1; break;
    case Qt::Key_Q: u = -1; break;
    default: ImageView::keyPressEvent(event); return;
    }
    if (!event->isAutoRepeat()) {
        // A new run of held keys is a new undo step; keys pressed while others are held join it.
        if (flyKeysHeld_.isEmpty()) flyKey_ = nextMergeKey();
        flyKeysHeld_.insert(event->key());
    } else if (flyKey_ == 0) {
        flyKey_ = nextMergeKey();
    }
    const double step = (event->modifiers() & Qt::ShiftModifier) ? 0.2 : 0.05;
    doc_->undoStack()->push(
        new EditCameraCommand(doc_, flyCamera(doc_->scene().camera, r * step, u * step, f * step), flyKey_, tr("Fly")));
}

void Viewport::focusOutEvent(QFocusEvent* event) {
    // Releases that go to another widget never reach us: the next press starts a new step.
    flyKeysHeld_.clear();
    ImageView::focusOutEvent(event);
}

void Viewport::keyReleaseEvent(QKeyEvent* event) {
    if (!event->isAutoRepeat()) flyKeysHeld_.remove(event->key());
    ImageView::keyReleaseEvent(event);
}

}  // namespace lucerna
