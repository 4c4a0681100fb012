#pragma once
// What `lucerna grid --task-area` adds to a task area's grid (README, "Task areas"): its
// surrounding zone and background area, computed with it, and EN 12464-1:2021's figures (Ez over
// the area, the room's walls and ceiling; render/photometry/task_area_figures.h), computed after
// it, with the checks of all of them in the command's words.

#include "render/photometry/zone_grids.h"
#include "render/photometry/task_area_figures.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna::cli {

// The 2021 figures to compute: what the requirement asks for (extrasFor), with --cylindrical
// and --room-surfaces added whether it asks or not, nothing with --horizontal-only.
TaskAreaExtrasRequest requestedExtras(const ActivityRequirement* requirement, bool cylindrical, bool roomSurfaces,
                                      bool horizontalOnly);

// The lines of what was computed: describeExtras' (Ez, the modelling ratio against `horizontal`,
// walls, ceiling), then how far each calculation got ("Ez: error bar (95%) at most ...",
// "room surfaces: 5 grids, 180 points, ...").
std::vector<std::string> extrasLines(const TaskAreaExtras& extras, const GridStatistics& horizontal);

}  // namespace lucerna::cli
