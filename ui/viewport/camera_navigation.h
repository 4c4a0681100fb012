#pragma once
// The viewport's camera moves and the projection it draws its overlays with, as pure functions
// on SPEC.md cameras so that they can be tested without a window. Every move keeps the camera
// valid: the target never reaches the position and the view never becomes parallel to up.

#include "core/scene/scene.h"

#include <optional>

namespace lucerna {

// Turns the camera about its target: yaw about the up vector, pitch about the camera's right
// axis (radians). The pitch stops a little short of looking straight along up.
Camera orbitCamera(const Camera& camera, double yaw, double pitch);
// Slides position and target together by fractions of the view's height at the target's distance
// (dx to the right, dy up), so the scene follows the mouse.
Camera panCamera(const Camera& camera, double dx, double dy);
// Moves the position toward the target by `factor` of the distance (factor < 1 comes closer).
Camera dollyCamera(const Camera& camera, double factor);
// Flies the camera: slides position and target together by `right`, `up` (along the camera's
// up vector) and `forward` (along the view), each in units of the distance to the target, so
// that a step is the same share of the view whatever the scene's scale.
Camera flyCamera(const Camera& camera, double right, double up, double forward);

// The camera looking along its present direction at the centre of the box [lo, hi], back far
// enough that the box's bounding sphere fits the narrower of the two fields of view.
Camera framedCamera(const Camera& camera, const V3d& lo, const V3d& hi);

// Raster position (x right, y down, in [0, W] x [0, H] of the camera's resolution) of a world
// point by SPEC.md's camera model; nothing when the point is behind the camera.
std::optional<V2f> projectToRaster(const Camera& camera, const V3d& point);

}  // namespace lucerna
