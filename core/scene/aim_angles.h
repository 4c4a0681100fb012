#pragma once
// A light's aim as a designer reads it: a tilt from straight down and a compass bearing, instead
// of the scene's direction vector (SPEC.md: a light's `direction`, y up).
//
// Conventions. Tilt is the angle in degrees between the direction and straight down (0, -1, 0):
// 0 hangs straight down, 90 is horizontal, 180 points straight up. Azimuth is the bearing in
// degrees of the direction's horizontal part, clockwise seen from above, from the site's north
// (SPEC.md section 5: `north`, default -z; east = north x up, +x by default): 0 = north,
// 90 = east, 180 = south, 270 = west.

#include "core/scene/scene.h"

namespace lucerna {

struct AimAngles {
    double tiltDeg = 0;     // [0, 180]
    double azimuthDeg = 0;  // [0, 360)
};

// The site's north made horizontal and unit: the scene's `north`, or -z without a site (or with a
// north that has no horizontal part).
V3d horizontalNorth(const Scene& scene);

// The angles of a non-zero `direction` (any length). A vertical direction (tilt 0 or 180) has no
// bearing: its azimuth is 0. `north` is horizontal and unit (horizontalNorth).
AimAngles aimAngles(const V3d& direction, const V3d& north);
// The unit direction with those angles (any azimuth, taken modulo 360; a tilt outside [0, 180]
// is clamped to it). aimDirection(aimAngles(d, n), n) is d.normalized() to rounding.
V3d aimDirection(const AimAngles& angles, const V3d& north);

}  // namespace lucerna
