#include "ui/viewport.h"

#include "ui/camera_navigation.h"
#include "ui/commands/light_commands.h"
#include "ui/commands/scene_commands.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <cmath>

namespace lucerna {

int nextMergeKey() {
    // Above the small fixed keys the property panel uses for its fields.
    static int key = 1 << 20;
    return ++key;
}

Viewport::Viewport(Document* doc, const YieldGate& gate, QWidget* parent)
    : ImageView(parent), doc_(doc), gate_(gate) {
    setPlaceholder(tr("Preparing the live preview..."));
    setMouseTracking(false);
    setFocusPolicy(Qt::ClickFocus);
    connect(doc_, &Document::changed, this, qOverload<>(&QWidget::update));
}

void Viewport::setSelectedLight(int index) {
    selected_ = index;
    update();
}

std::optional<QPointF> Viewport::lightMarker(int index) const {
    const Scene& scene = doc_->scene();
    if (index < 0 || index >= int(scene.lights.size())) return std::nullopt;
    const Light& light = scene.lights[size_t(index)];
    const QRectF r = imageRect();
    if (light.type == LightType::Directional || r.isEmpty()) return std::nullopt;
    const auto p = projectToRaster(scene.camera, light.position);
    if (!p) return std::nullopt;
    return QPointF(r.left() + p->x / scene.camera.width * r.width(), r.top() + p->y / scene.camera.height * r.height());
}

int Viewport::lightAt(const QPointF& pos) const {
    int best = -1;
    double bestDist = 10.0;  // pixels
    for (int i = 0; i < int(doc_->scene().lights.size()); ++i)
        if (const auto m = lightMarker(i)) {
            const double d = std::hypot(m->x() - pos.x(), m->y() - pos.y());
            if (d < bestDist) bestDist = d, best = i;
        }
    return best;
}

void Viewport::paintOverlay(QPainter& painter) {
    painter.setRenderHint(QPainter::Antialiasing);
    const Scene& scene = doc_->scene();
    for (int i = 0; i < int(scene.lights.size()); ++i) {
        const auto m = lightMarker(i);
        if (!m) continue;
        const Light& light = scene.lights[size_t(i)];
        const bool selected = i == selected_;
        if (light.type == LightType::Spot) {
            // The spot's axis, a tenth of the way to the target's distance.
            const double len = 0.1 * (scene.camera.target - scene.camera.position).length();
            const V3d tip = light.position + light.direction.normalized() * len;
            if (const auto t = projectToRaster(scene.camera, tip)) {
                const QRectF r = imageRect();
                const QPointF tp(r.left() + t->x / scene.camera.width * r.width(),
                                 r.top() + t->y / scene.camera.height * r.height());
                painter.setPen(QPen(QColor(255, 210, 60), 2));
                painter.drawLine(*m, tp);
            }
        }
        painter.setPen(QPen(selected ? Qt::white : QColor(40, 40, 40), selected ? 3 : 1.5));
        painter.setBrush(QColor(255, 210, 60));
        painter.drawEllipse(*m, selected ? 7 : 5, selected ? 7 : 5);
    }
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    if (drag_ != Drag::None) return;
    last_ = event->position();
    mergeKey_ = nextMergeKey();
    wheelKey_ = nextMergeKey();
    if (event->button() == Qt::LeftButton) {
        dragLight_ = lightAt(event->position());
        if (dragLight_ >= 0) {
            emit lightClicked(dragLight_);
            drag_ = Drag::MoveLight;
        } else {
            drag_ = Drag::Orbit;
        }
    } else if (event->button() == Qt::RightButton || event->button() == Qt::MiddleButton) {
        drag_ = Drag::Pan;
    }
    // The preview comes first on the cores while the user interacts.
    if (drag_ != Drag::None) hold_ = std::make_unique<YieldGate::Scope>(gate_.counter());
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    const QRectF r = imageRect();
    if (drag_ == Drag::None || r.isEmpty()) return;
    const QPointF delta = event->position() - last_;
    last_ = event->position();
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
        doc_->undoStack()->push(new EditLightCommand(
            doc_, dragLight_, light, mergeKey_, tr("Move %1").arg(QString::fromStdString(light.name))));
        break;
    }
    case Drag::None: break;
    }
}

void Viewport::mouseReleaseEvent(QMouseEvent*) { endDrag(); }

void Viewport::endDrag() {
    drag_ = Drag::None;
    dragLight_ = -1;
    hold_.reset();
}

void Viewport::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0) return;
    // Successive wheel steps merge until some other interaction takes a new key.
    if (drag_ != Drag::None) return;
    doc_->undoStack()->push(
        new EditCameraCommand(doc_, dollyCamera(doc_->scene().camera, std::pow(0.85, steps)), wheelKey_, tr("Zoom")));
}

}  // namespace lucerna
