#include "ui/viewport/camera_navigation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {
// Rodrigues' rotation of v about the unit axis k.
V3d rotate(const V3d& v, const V3d& k, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + k.cross(v) * s + k * (k.dot(v) * (1 - c));
}

struct Basis {
    V3d f, r, u;
};
Basis basisOf(const Camera& c) {
    Basis b;
    b.f = (c.target - c.position).normalized();
    b.r = b.f.cross(c.up).normalized();
    b.u = b.r.cross(b.f);
    return b;
}
}  // namespace

Camera orbitCamera(const Camera& camera, double yaw, double pitch) {
    Camera c = camera;
    const V3d up = camera.up.normalized();
    V3d offset = camera.position - camera.target;
    offset = rotate(offset, up, -yaw);
    // Limit the pitch so that the view stays at least ~2 degrees away from the up axis.
    const double dist = offset.length();
    const double elevation = std::asin(std::clamp(offset.dot(up) / dist, -1.0, 1.0));
    const double limit = std::numbers::pi / 2 - 0.035;
    const double target = std::clamp(elevation + pitch, -limit, limit);
    const V3d right = up.cross(offset).normalized();
    offset = rotate(offset, right, -(target - elevation));
    c.position = camera.target + offset;
    return c;
}

Camera panCamera(const Camera& camera, double dx, double dy) {
    const Basis b = basisOf(camera);
    const double dist = (camera.target - camera.position).length();
    const double height = 2 * dist * std::tan(radians(camera.fovYDeg) / 2);
    const V3d shift = (b.r * -dx + b.u * -dy) * height;
    Camera c = camera;
    c.position += shift;
    c.target += shift;
    return c;
}

Camera dollyCamera(const Camera& camera, double factor) {
    Camera c = camera;
    const V3d offset = camera.position - camera.target;
    // Never onto the target (SPEC.md: the target must differ from the position).
    c.position = camera.target + offset * std::max(factor, 1e-3);
    return c;
}

Camera flyCamera(const Camera& camera, double right, double up, double forward) {
    const Basis b = basisOf(camera);
    const double dist = (camera.target - camera.position).length();
    const V3d shift = (b.r * right + camera.up.normalized() * up + b.f * forward) * dist;
    Camera c = camera;
    c.position += shift;
    c.target += shift;
    return c;
}

std::optional<V2f> projectToRaster(const Camera& camera, const V3d& point) {
    const Basis b = basisOf(camera);
    const V3d d = point - camera.position;
    const double z = d.dot(b.f);
    if (z <= 1e-9) return std::nullopt;
    const double t = std::tan(radians(camera.fovYDeg) / 2);
    const double aspect = double(camera.width) / camera.height;
    // Inverse of SPEC.md's f + (2x/W - 1)(W/H) t r + (1 - 2y/H) t u.
    const double sx = d.dot(b.r) / (z * t * aspect), sy = d.dot(b.u) / (z * t);
    return V2f(float((sx + 1) * 0.5 * camera.width), float((1 - sy) * 0.5 * camera.height));
}

Camera framedCamera(const Camera& camera, const V3d& lo, const V3d& hi) {
    Camera c = camera;
    const V3d centre = (lo + hi) * 0.5;
    const double radius = std::max((hi - lo).length() * 0.5, 1e-9);
    V3d forward = camera.target - camera.position;
    if (forward.length() <= 0) forward = V3d(0, 0, -1);
    forward.normalize();
    const double halfY = camera.fovYDeg * std::numbers::pi / 360;
    const double halfX = std::atan(std::tan(halfY) * double(camera.width) / std::max(camera.height, 1));
    const double distance = radius / std::sin(std::min(halfX, halfY));
    c.target = centre;
    c.position = centre - forward * distance;
    return c;
}

}  // namespace lucerna
