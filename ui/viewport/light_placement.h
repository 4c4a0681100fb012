#pragma once
// Placing and aiming lights by clicking a surface (issue 6). A placed light stands off the
// surface along its normal, on the side the user looked at it from; a placed spot aims along
// that normal, into the room. Aiming turns a spot toward the clicked point, and makes a
// directional light fall squarely on the clicked surface (it travels against the normal). A
// luminaire aims like a spot: its nadir at the clicked point.

#include "core/scene/scene.h"
#include "render/trace/surface_pick.h"

#include <optional>
#include <string>

namespace lucerna {

// How far a placed light stands off the surface, in scene units: 0.25 m (through
// meters_per_unit), but at most a tenth of the diagonal of the geometry's bounding box, so
// that small scenes (a product in millimetres, the Cornell box) keep the light close.
double placementOffset(double metersPerUnit, double geometryDiagonal);

// A new light of `type` (point or spot; the defaults of defaultLight()) placed at `hit`.
Light placedLight(const Scene& scene, LightType type, const std::string& name, const SurfaceHit& hit, double offset);

// The light aimed at `hit`: a spot (or a luminaire's nadir) points at the hit point, a
// directional light travels against the surface's normal. Nothing for point lights and for a
// light sitting on the point itself.
std::optional<Light> aimedLight(const Light& light, const SurfaceHit& hit);

}  // namespace lucerna
