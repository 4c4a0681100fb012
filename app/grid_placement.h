#pragma once
// Where `lucerna grid` puts its points, for the commands that measure the same points (grid,
// annual): a work plane over the scene (height above its lowest geometry, a border along the
// walls) or one of the scene's task areas.

#include "core/photometry/calculation_grid.h"
#include "core/scene/scene.h"

#include <optional>
#include <string>

namespace lucerna::cli {

// The work plane at heightM (metres above the lowest geometry) inside a border of borderM, with
// `spacing` (EN 12464-1's rule when absent) and `name`. UsageError for a degenerate plane.
CalculationGrid workPlaneGridOf(const Scene& scene, double heightM, double borderM,
                                std::optional<double> spacing, const std::string& name);

// The scene's task area of that name; UsageError naming the areas it has when there is none.
const TaskArea& taskAreaOf(const Scene& scene, const std::string& name);

}  // namespace lucerna::cli
