#include "core/scene/aim_angles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {
const V3d kUp(0, 1, 0);
constexpr double kDegrees = 180.0 / std::numbers::pi;
}  // namespace

V3d horizontalNorth(const Scene& scene) {
    if (scene.site) {
        const V3d n(scene.site->north.x, 0, scene.site->north.z);
        if (n.length() > 1e-12) return n.normalized();
    }
    return V3d(0, 0, -1);
}

AimAngles aimAngles(const V3d& direction, const V3d& north) {
    const V3d d = direction.normalized();
    const V3d east = north.cross(kUp);
    AimAngles a;
    // atan2 of the vertical and horizontal parts: accurate near straight down and up, where acos
    // of the dot product loses half the digits.
    const double horizontal = std::hypot(d.x, d.z);
    a.tiltDeg = std::atan2(horizontal, -d.y) * kDegrees;
    if (horizontal > 1e-12) {
        const double bearing = std::atan2(d.dot(east), d.dot(north)) * kDegrees;
        a.azimuthDeg = bearing < 0 ? bearing + 360 : bearing;
        if (a.azimuthDeg >= 360) a.azimuthDeg = 0;  // -tiny + 360 rounds to 360
    }
    return a;
}

V3d aimDirection(const AimAngles& angles, const V3d& north) {
    const double tilt = std::clamp(angles.tiltDeg, 0.0, 180.0) / kDegrees;
    const double azimuth = std::fmod(angles.azimuthDeg, 360.0) / kDegrees;
    const V3d east = north.cross(kUp);
    const V3d across = north * std::cos(azimuth) + east * std::sin(azimuth);
    return (across * std::sin(tilt) - kUp * std::cos(tilt)).normalized();
}

}  // namespace lucerna
