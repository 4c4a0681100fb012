#pragma once
// The room summary of a scene with rooms (README, "Rooms" and "Reports"), room by room: each
// room's dimensions, the reflectances of its floor, walls and ceiling, its openings, the
// maintenance factor of the lights in it, and its walls' and ceiling's illuminance where a task
// area's requirement had them computed. A scene without rooms is summarised as one extent
// (room_summary.h).

#include "core/photometry/lighting_standards.h"
#include "core/scene/scene.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct RoomEntry {
    std::string name;
    bool drawn = false;             // an outline (parametric), else marked on existing objects
    double floorAreaM2 = 0;         // roomFloorArea
    double widthM = 0, depthM = 0;  // the outline's extent in plan (x by z); marked: its surfaces'
    double heightM = 0;             // floor to ceiling; marked: its surfaces' extent in y
    std::optional<double> wallAreaM2;  // drawn: the walls less the openings
    // Floor, walls, ceiling: the material and its reflectance (luminance of the diffuse albedo):
    // a drawn room's named materials (roomReflectances), a marked room's main surfaces among its
    // own objects (room_summary.h's rule); absent for a material without a diffuse part.
    std::array<std::string, 3> materials;
    std::array<std::optional<double>, 3> reflectances;
    int windows = 0, doors = 0, plainOpenings = 0;
    double openingAreaM2 = 0;
    // The factors of the lights switched on inside the room (in plan within its outline or
    // bounds, and between its floor and ceiling); with none there, the scene's (lightsInside 0).
    MaintenanceRange maintenance;
    int lightsInside = 0;
    // The walls' and ceiling's illuminance, when a task area in this room asked for them.
    std::optional<SurfaceIlluminance> walls, ceiling;
};

struct RoomsSummary {
    std::vector<RoomEntry> rooms;
};

// The rooms of `scene` (as loaded: the world meshes resolved), without illuminance.
RoomsSummary roomsSummary(const Scene& scene);

}  // namespace lucerna
