#include "ui/viewport/light_gizmo.h"

#include "render/trace/surface_pick.h"

#include <cmath>

namespace lucerna {

namespace {
double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b) {
    const QPointF ab = b - a, ap = p - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double s = len2 > 0 ? std::clamp(QPointF::dotProduct(ap, ab) / len2, 0.0, 1.0) : 0.0;
    const QPointF d = ap - ab * s;
    return std::hypot(d.x(), d.y());
}

V3d forwardOf(const Camera& c) { return (c.target - c.position).normalized(); }
}  // namespace

QPointF ViewMapping::toRaster(const QPointF& widget) const {
    return {(widget.x() - rect_.left()) / rect_.width() * camera_.width,
            (widget.y() - rect_.top()) / rect_.height() * camera_.height};
}

QPointF ViewMapping::fromRaster(double x, double y) const {
    return {rect_.left() + x / camera_.width * rect_.width(), rect_.top() + y / camera_.height * rect_.height()};
}

std::optional<QPointF> ViewMapping::toWidget(const V3d& world) const {
    // projectToRaster() in double precision: drags are solved back through rayThrough().
    const V3d f = forwardOf(camera_);
    const V3d r = f.cross(camera_.up).normalized(), u = r.cross(f);
    const V3d d = world - camera_.position;
    const double z = d.dot(f);
    if (z <= 1e-9 * std::max(d.length(), 1e-300)) return std::nullopt;
    const double t = std::tan(radians(camera_.fovYDeg) / 2), aspect = double(camera_.width) / camera_.height;
    const double sx = d.dot(r) / (z * t * aspect), sy = d.dot(u) / (z * t);
    return fromRaster((sx + 1) * 0.5 * camera_.width, (1 - sy) * 0.5 * camera_.height);
}

V3d ViewMapping::rayThrough(const QPointF& widget) const {
    const QPointF r = toRaster(widget);
    return cameraRayDirection(camera_, r.x(), r.y());
}

double ViewMapping::worldPerPixel(const V3d& world) const {
    const double depth = std::max((world - camera_.position).dot(forwardOf(camera_)), 1e-9);
    return 2 * depth * std::tan(radians(camera_.fovYDeg) / 2) / std::max(rect_.height(), 1.0);
}

std::optional<LightGizmo> LightGizmo::of(const Light& light, const ViewMapping& view) {
    if (light.type == LightType::Directional || light.type == LightType::Sun || !view.isValid()) return std::nullopt;
    const auto centre = view.toWidget(light.position);
    if (!centre) return std::nullopt;
    LightGizmo g;
    g.centre = *centre;
    const double perPixel = view.worldPerPixel(light.position);
    g.axisLength = kAxisPixels * perPixel;
    const std::array<V3d, 3> axes{V3d(1, 0, 0), V3d(0, 1, 0), V3d(0, 0, 1)};
    for (size_t i = 0; i < 3; ++i) g.axisTips[i] = view.toWidget(light.position + axes[i] * g.axisLength);
    if (light.type == LightType::Spot || light.type == LightType::Luminaire) {
        g.aimLength = kAimPixels * perPixel;
        g.aimTip = view.toWidget(light.position + light.direction.normalized() * g.aimLength);
    }
    return g;
}

GizmoHandle LightGizmo::handleAt(const QPointF& widget) const {
    const auto near = [&](const QPointF& p) { return std::hypot(p.x() - widget.x(), p.y() - widget.y()); };
    if (aimTip && near(*aimTip) <= kGrabPixels + 2) return GizmoHandle::Aim;
    // The marker's own disc belongs to the marker (a move in the image plane).
    if (near(centre) <= kGrabPixels + 1) return GizmoHandle::None;
    GizmoHandle best = GizmoHandle::None;
    double bestDistance = kGrabPixels;
    for (size_t i = 0; i < 3; ++i) {
        // An arrow that points at the viewer is a dot under the marker: nothing to drag along.
        if (!axisTips[i] || std::hypot(axisTips[i]->x() - centre.x(), axisTips[i]->y() - centre.y()) < kGrabPixels + 4)
            continue;
        const double d = distanceToSegment(widget, centre, *axisTips[i]);
        if (d <= bestDistance) bestDistance = d, best = GizmoHandle(int(GizmoHandle::X) + int(i));
    }
    return best;
}

V3d dragAlongAxis(const ViewMapping& view, const V3d& start, const V3d& axis, const QPointF& pressed, const QPointF& now) {
    const V3d a = axis.normalized();
    const V3d o = view.camera().position;
    // Parameter along the axis line of its point closest to the mouse ray through `widget`.
    const auto along = [&](const QPointF& widget) -> std::optional<double> {
        const V3d r = view.rayThrough(widget);
        const V3d w0 = start - o;
        const double b = a.dot(r), d = a.dot(w0), e = r.dot(w0);
        const double denom = 1 - b * b;
        // Within about 6 degrees of the view, the axis is a dot on screen: a drag means nothing.
        if (denom < 0.01) return std::nullopt;
        return (b * e - d) / denom;
    };
    const auto s0 = along(pressed), s1 = along(now);
    if (!s0 || !s1) return start;
    // Bounded, so that a drag past the axis's vanishing point cannot throw the light away.
    const double limit = 100 * std::max((start - o).length(), 1e-9);
    return start + a * std::clamp(*s1 - *s0, -limit, limit);
}

std::optional<V3d> aimThroughPlane(const ViewMapping& view, const V3d& position, const V3d& tip, const QPointF& now) {
    const V3d f = forwardOf(view.camera());
    const V3d o = view.camera().position;
    const V3d r = view.rayThrough(now);
    const double rf = r.dot(f);
    if (rf <= 1e-9) return std::nullopt;
    const double t = (tip - o).dot(f) / rf;
    if (t <= 0) return std::nullopt;
    const V3d d = o + r * t - position;
    if (d.length() <= 1e-12 * std::max(1.0, position.length())) return std::nullopt;
    return d.normalized();
}

}  // namespace lucerna
