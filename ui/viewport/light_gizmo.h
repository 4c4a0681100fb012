#pragma once
// The geometry of the viewport's light gizmo, apart from any widget so that it can be tested:
// where the camera's image lies in the widget (ViewMapping), where the selected light's handles
// are drawn (three world-axis arrows, and for a spot or luminaire an aim handle at the tip of its
// axis), which
// handle is under the mouse, and what a drag of a handle does to the light.

#include "core/scene/scene.h"

#include <QPointF>
#include <QRectF>

#include <array>
#include <optional>

namespace lucerna {

// SPEC.md's camera drawn into a rectangle of the widget (the whole raster, aspect kept).
class ViewMapping {
public:
    ViewMapping(const Camera& camera, const QRectF& imageRect) : camera_(camera), rect_(imageRect) {}

    const Camera& camera() const { return camera_; }
    bool isValid() const { return !rect_.isEmpty(); }
    // Where the picture is in the widget.
    const QRectF& rect() const { return rect_; }
    // Raster position (camera pixels) of a widget point, and back.
    QPointF toRaster(const QPointF& widget) const;
    QPointF fromRaster(double x, double y) const;
    // Widget position of a world point; nothing when it is behind the camera.
    std::optional<QPointF> toWidget(const V3d& world) const;
    // Unit direction of the camera ray through a widget point.
    V3d rayThrough(const QPointF& widget) const;
    // World length that one widget pixel spans at the depth of `world` (> 0).
    double worldPerPixel(const V3d& world) const;

private:
    Camera camera_;
    QRectF rect_;
};

enum class GizmoHandle { None, X, Y, Z, Aim };

struct LightGizmo {
    // Screen lengths of the handles, in widget pixels.
    static constexpr double kAxisPixels = 60, kAimPixels = 95, kGrabPixels = 7;

    QPointF centre;
    // Tips of the x, y and z arrows; nothing for an axis whose tip is behind the camera.
    std::array<std::optional<QPointF>, 3> axisTips;
    std::optional<QPointF> aimTip;  // spots and luminaires (their nadir)
    double axisLength = 0;          // world length of each arrow
    double aimLength = 0;           // world length of the aim handle

    // The gizmo of a light as seen through `view`; nothing for directional lights and lights
    // behind the camera.
    static std::optional<LightGizmo> of(const Light& light, const ViewMapping& view);
    // The handle within grabbing distance of a widget point (the aim tip first, then the
    // arrow closest to the point); None elsewhere, the light's own marker included, and for
    // arrows too short on screen to grab (pointing at the viewer).
    GizmoHandle handleAt(const QPointF& widget) const;
};

// Where a light dragged by an axis arrow goes: `start` moved along the unit world `axis` by as
// much as the mouse moved along the axis's line on screen, from `pressed` to `now` (the closest
// points of the mouse rays to the axis line). Exact under perspective: the point of the axis
// that was grabbed stays under the mouse. `start` itself when the axis points almost along the
// view.
V3d dragAlongAxis(const ViewMapping& view, const V3d& start, const V3d& axis, const QPointF& pressed, const QPointF& now);

// A spot's direction after its aim handle is dragged to `now`: toward the point where the mouse
// ray meets the plane through `tip` (the handle's position when the drag began) parallel to the
// image plane. Nothing when the mouse ray misses that plane or the point is the light's position.
std::optional<V3d> aimThroughPlane(const ViewMapping& view, const V3d& position, const V3d& tip, const QPointF& now);

}  // namespace lucerna
