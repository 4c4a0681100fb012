#include "app/grid_placement.h"

#include "app/cli_support.h"
#include "core/scene/scene_geometry.h"

#include <algorithm>
#include <stdexcept>

namespace lucerna::cli {

CalculationGrid workPlaneGridOf(const Scene& scene, double heightM, double borderM, std::optional<double> spacing,
                                const std::string& name) {
    const SceneBounds b = sceneBounds(scene);
    CalculationGrid grid;
    try {
        grid = workPlaneGrid(b.lo, b.hi, scene.metersPerUnit, heightM, borderM);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("grid: ") + e.what());
    }
    grid.name = name;
    grid.spacingMeters = spacing;
    return grid;
}

const TaskArea& taskAreaOf(const Scene& scene, const std::string& name) {
    const auto area = std::find_if(scene.taskAreas.begin(), scene.taskAreas.end(),
                                   [&](const TaskArea& a) { return a.grid.name == name; });
    if (area != scene.taskAreas.end()) return *area;
    std::string names;
    for (const TaskArea& a : scene.taskAreas) names += (names.empty() ? "" : ", ") + a.grid.name;
    throw UsageError("--task-area: the scene has no task area '" + name + "'" +
                     (names.empty() ? std::string(" (it has none)") : " (it has: " + names + ")"));
}

}  // namespace lucerna::cli
