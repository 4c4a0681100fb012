#pragma once
// The illuminance of a room's walls and ceiling (EN 12464-1:2021, 5.2.4: the average
// illuminance of the walls and of the ceiling, with its uniformity, as a measure of the room's
// brightness): calculation grids laid on the faces of the room's box and moved onto the surfaces
// found there.
//
// Each of the box's four walls and its ceiling gets a grid (core/photometry/calculation_grid.h,
// EN 12464-1's spacing for that face), facing into the room. Each point is then moved along
// the face's normal onto the first opaque surface a ray from inside the room meets within
// kSurfaceDepthMeters of the face (a wall's inner face, thick or thin, a window reveal), and set
// a little in front of it: the sensor measures the light that reaches the surface there. A point
// whose ray meets nothing that close (an opening, or no wall there at all), crosses a glazing
// pane before its surface (a window) or meets glass (a dielectric object) keeps its place on the
// box's face and is left out of the figures, as EN 12464-1 computes the walls' surfaces, not
// their openings.

#include "core/photometry/grid_error_bars.h"
#include "render/photometry/grid_calculation.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lucerna {

inline constexpr double kSurfaceDepthMeters = 0.6;  // the deepest wall or reveal looked for

struct RoomSurfaceGrid {
    std::string name;        // "wall 1" (x = lo), "wall 2" (x = hi), "wall 3" (z = lo), "wall 4" (z = hi), "ceiling"
    bool ceiling = false;
    CalculationGrid grid;    // on the box's face, facing into the room
    GridLayout layout;
    std::vector<V3d> points; // the sensors: in front of the surfaces found (scene units)
    std::vector<uint8_t> opening;  // per point, 1 at a window, an opening or no surface: left out
    double cellAreaM2 = 0;
};

// The grids of the box [lo, hi] (scene units, y up), traced against `scene`. The sensors stand
// max(1 cm, 3e-4 of the scene's radius) in front of their surfaces: beyond grid_diagnosis.h's
// test of points on a surface, near enough that the light reaching them is the surface's.
std::vector<RoomSurfaceGrid> roomSurfaceGrids(const RenderScene& scene, const V3d& lo, const V3d& hi,
                                              double metersPerUnit);

// Figures over several grids together (the four walls): Eavg weighted by the points' cell areas,
// Emin, Emax and U0 over all their points, and the error bars as gridErrorBars gives them.
struct SurfaceFigures {
    GridStatistics stats;
    GridErrorBars errors;
    bool errorKnown = true;  // false: some grid's method backs no error bar (grid_calculation.h)
    int points = 0;          // in the figures
    int leftOut = 0;         // inside geometry, on a surface or glass
};
SurfaceFigures combinedSurfaceFigures(const std::vector<const RoomSurfaceGrid*>& grids,
                                      const std::vector<const GridResult*>& results);

// The walls' and the ceiling's figures of a scene as rendered (computeSceneGrid's scene: lights
// switched off left out, maintenance factors applied), each grid computed with `settings`
// (quantity planar) in turn; progress in ctx over the five grids, mapped onto [progressBase,
// progressBase + progressShare]. Cancelled: what was computed.
struct RoomSurfaceResult {
    std::vector<RoomSurfaceGrid> grids;
    std::vector<GridResult> results;  // one per grid (fewer when cancelled)
    SurfaceFigures walls, ceiling;
    double seconds = 0;
    bool complete = false;
};
RoomSurfaceResult computeRoomSurfaces(const SceneSnapshot& scene, const V3d& lo, const V3d& hi,
                                      const GridSettings& settings, TaskContext& ctx, double progressBase = 0,
                                      double progressShare = 1);

}  // namespace lucerna
