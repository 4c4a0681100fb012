#pragma once
// A first camera for an imported building: inside its largest room, at eye height, looking
// across the room (an architect's model seen from outside its walls is a black first image).
// Rooms are found by casting rays: on a horizontal lattice over the model, a point at eye height
// (1.6 m above the floor found below it) is inside a room when a ceiling lies above it and walls
// close it in all eight horizontal directions; neighbouring inside points with nothing between
// them are the same room; the room with the most points is the largest. The camera stands where,
// at least 0.6 m from the walls, the view along one of the eight directions is longest, and
// looks that way.

#include "core/scene/scene.h"

#include <optional>

namespace lucerna {

// The camera (base's resolution, a 60 degree vertical field of view, y up) in the largest room
// of the scene's geometry; nothing when no enclosed room is found (an open model, a lone object)
// or the geometry cannot be traced.
std::optional<Camera> cameraInLargestRoom(const Scene& scene, const Camera& base);

}  // namespace lucerna
