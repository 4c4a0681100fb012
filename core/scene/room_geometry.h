#pragma once
// A rectangular room built from its dimensions (Edit > Add Room): floor, ceiling and four walls as
// quads facing into the room, with the three materials a lighting calculation asks for (the
// reflectances of floor, walls and ceiling, EN 12464-1's usual ranges as defaults).

#include "core/scene/scene.h"

#include <string>
#include <vector>

namespace lucerna {

struct RoomSpec {
    std::string name = "room";
    V3d corner{0, 0, 0};        // the floor's corner of least x and z (scene units)
    double width = 6, depth = 4, height = 3;  // along x, z and y, in metres
    double floorReflectance = 0.2, wallReflectance = 0.5, ceilingReflectance = 0.7;
};

struct RoomParts {
    std::vector<Material> materials;  // floor, walls, ceiling
    std::vector<Object> objects;      // floor, ceiling, then the walls at x min, x max, z min, z max
};

// The room's objects (quads; world meshes resolved) and materials, named after spec.name and made
// unique against `scene` (objects and lights together, materials apart, as SPEC.md asks).
// Throws std::invalid_argument when a dimension is not positive or a reflectance is outside [0, 1].
RoomParts makeRoom(const RoomSpec& spec, const Scene& scene);

}  // namespace lucerna
