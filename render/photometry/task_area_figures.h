#pragma once
// The figures EN 12464-1:2021 adds to a task area's Em, U0 and UGR (5.2.4, 5.2.6): the mean
// cylindrical illuminance Ez over the activity area at 1.2 m above the floor for seated work or
// 1.6 m standing, with its uniformity, and the average illuminance of the room's walls and of its
// ceiling, with theirs. `lucerna grid --task-area`, the Calculation grid dock and the report
// compute them here, so that the three agree for the same settings.

#include "core/photometry/lighting_standards.h"
#include "render/photometry/room_surfaces.h"

#include <optional>
#include <string>

namespace lucerna {

inline constexpr double kSeatedCylindricalHeightM = 1.2, kStandingCylindricalHeightM = 1.6;

// The room a task area lies in, as a box: a room of the scene (Scene::rooms) whose outline holds
// the area's centre and whose floor-to-ceiling span holds its height (a marked room: the bounds
// of its surfaces); else the scene's bounds, whose lowest point is then taken as the floor.
struct TaskAreaRoom {
    V3d lo{0, 0, 0}, hi{1, 1, 1};  // scene units, y up
    double floorLevel = 0;         // y of the floor under the area, scene units
    std::string description;       // "room 'Office'", "the scene's bounds"
};
TaskAreaRoom taskAreaRoom(const Scene& scene, const TaskArea& area);

// The grid of Ez: the task area's rectangle at the posture's height above the room's floor,
// facing up (its normal is the cylinder's axis), with the area's spacing. Throws
// std::invalid_argument (one line) as layoutGrid does.
CalculationGrid cylindricalGrid(const TaskArea& area, const TaskAreaRoom& room, double metersPerUnit);

struct CylindricalFigures {
    CalculationGrid grid;
    GridLayout layout;
    GridResult result;
    double heightAboveFloorM = 0;
    SurfaceIlluminance figures;  // over the points not inside geometry
};

// Which of the 2021 figures to compute.
struct TaskAreaExtrasRequest {
    bool cylindrical = true;
    bool roomSurfaces = true;
};

struct TaskAreaExtras {
    TaskAreaRoom room;
    std::optional<CylindricalFigures> cylindrical;    // absent: not asked, or cancelled first
    std::optional<RoomSurfaceResult> roomSurfaces;  // absent: not asked, or cancelled first
    bool complete = false;                            // all that was asked, not cancelled
};

// Computes what `request` asks for the task area of `scene` (computeSceneGrid's scene), each with
// `settings` (the quantity set as each needs). Progress in ctx: Ez first (a third of it when
// both are asked), then the five surface grids.
TaskAreaExtras computeTaskAreaExtras(const SceneSnapshot& scene, const TaskArea& area, const GridSettings& settings,
                                     const TaskAreaExtrasRequest& request, TaskContext& ctx);

// The request a requirement asks for: Ez where it states Ez, the surfaces where it states a wall
// or ceiling figure; nothing without a requirement.
TaskAreaExtrasRequest extrasFor(const ActivityRequirement* requirement);

// The error bars as SurfaceIlluminance carries them: absent when the method backs none.
SurfaceIlluminance surfaceIlluminance(const SurfaceFigures& figures);
// Fills figures.cylindrical, .walls and .ceiling from what was computed.
void addExtras(TaskAreaFigures& figures, const TaskAreaExtras& extras);

// Text lines for the CLI and the dock: "Ez at 1.20 m (seated), room 'Office': Eavg 212 lx +- 4
// lx, Emin ..., U0 0.61 +- 0.02 (35 points)", "walls: ...", "ceiling: ...", and the modelling
// ratio when Eh is given.
std::vector<std::string> describeExtras(const TaskAreaExtras& extras, const std::optional<GridStatistics>& horizontal);

}  // namespace lucerna
