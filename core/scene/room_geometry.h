#pragma once
// A parametric room's surfaces (README, "Rooms"; Room in core/scene/scene.h): the floor and the
// ceiling as its outline triangulated, a wall along each edge of the outline, all facing into the
// room, each wall with its openings cut out as real holes (its triangles leave them out), and a
// glazing pane in each window. What a lighting calculation asks of a room: the reflectances of
// floor, walls and ceiling (EN 12464-1's usual ranges as defaults).

#include "core/scene/plan_polygon.h"
#include "core/scene/scene.h"

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace lucerna {

// One wall of a parametric room: its outline edge and the horizontal unit normal into the room.
struct RoomWall {
    V2d from, to;     // plan (x, z), scene units
    double length = 0;
    V2d inward;
};

// The walls of a parametric room, in the outline's order (wall k is element k-1).
std::vector<RoomWall> roomWalls(const Room& room);

// Why the room cannot be built: the key at fault within the room ("name", "outline", "height",
// "materials.walls", "openings[2]", "openings[2].wall") and the problem in a few words; nothing
// when it can be. A marked room (no outline) needs only its name. A parametric room: a simple
// outline (outlineProblem), a positive height, its three materials among `materials`, and each
// opening on one of its walls, within the wall's length and under the ceiling, clear of the other
// openings of that wall; a door's sill 0; a window's glazing a glazing material.
struct RoomProblem {
    std::string key, problem;
};
std::optional<RoomProblem> roomProblem(const Room& room, const std::vector<Material>& materials);

// The surfaces of a parametric room as objects tagged with it, their world meshes resolved: the
// floor (facing up), the ceiling (facing down), walls 1 to n (facing in, their openings left
// out), then a pane of the window's glazing in each window (doors and plain openings are holes
// only). Named "ROOM floor", "ROOM ceiling", "ROOM wall K", "ROOM window K" (K counts the room's
// windows), each made unique against `taken` (the names of the scene's objects and lights
// besides these), which gains them. Rectangles are quads, other shapes inline meshes. Throws
// std::invalid_argument with roomProblem's reason ("outline: walls 1 and 3 cross ...").
std::vector<Object> roomSurfaces(const Room& room, const Scene& scene, std::set<std::string>& taken);

// The openings of a parametric room that hold no pane (doors, plain openings), each as its four
// corners (scene units) in its wall's plane: where daylight particles may enter the room besides
// its windows' panes (render/trace/lights/daylight_portals.h). None for a room that cannot be
// built (roomProblem) or a marked one.
std::vector<std::array<V3d, 4>> unglazedOpenings(const Room& room, const std::vector<Material>& materials);

// A parametric room's areas in square scene units: the floor (the ceiling's too), its walls with
// the openings taken out, and the openings.
struct RoomAreas {
    double floor = 0, walls = 0, openings = 0;
};
RoomAreas roomAreas(const Room& room);
// A room's floor area in square scene units: a drawn room's outline; a marked room's faces that
// face up or down (within 45 degrees) at the bottom of its shell (within a hundredth of its
// height).
double roomFloorArea(const Scene& scene, const Room& room);

// The names of openings as the window lists them: "window", "door", "opening".
const char* openingTypeName(OpeningType type);

}  // namespace lucerna
