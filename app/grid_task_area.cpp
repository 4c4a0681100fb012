#include "app/grid_task_area.h"

#include "core/number_format.h"
#include "core/photometry/grid_error_bars.h"
#include "render/photometry/grid_text.h"

#include <algorithm>

namespace lucerna::cli {

TaskAreaExtrasRequest requestedExtras(const ActivityRequirement* requirement, bool cylindrical, bool roomSurfaces,
                                      bool horizontalOnly) {
    if (horizontalOnly) return {false, false};
    TaskAreaExtrasRequest request = extrasFor(requirement);
    request.cylindrical = request.cylindrical || cylindrical;
    request.roomSurfaces = request.roomSurfaces || roomSurfaces;
    return request;
}

std::vector<std::string> extrasLines(const TaskAreaExtras& extras, const GridStatistics& horizontal) {
    std::vector<std::string> lines =
        describeExtras(extras, horizontal.counted > 0 ? std::optional(horizontal) : std::nullopt);
    if (extras.cylindrical) {
        const CylindricalFigures& c = *extras.cylindrical;
        lines.push_back("Ez grid: " + std::to_string(c.layout.nu) + " x " + std::to_string(c.layout.nv) + " points");
        for (const std::string& line : gridErrorLines(c.result, c.figures.grid.counted)) lines.back() += ", " + line;
    }
    if (extras.roomSurfaces) {
        const RoomSurfaceResult& r = *extras.roomSurfaces;
        size_t points = 0;
        std::string short_;
        for (size_t g = 0; g < r.grids.size(); ++g) {
            points += r.grids[g].points.size();
            if (g < r.results.size() && !r.results[g].converged) short_ += (short_.empty() ? "" : ", ") + r.grids[g].name;
        }
        double maxRelative = 0;
        for (const GridResult& result : r.results) maxRelative = std::max(maxRelative, result.maxRelativeError);
        lines.push_back("room surface grids: " + std::to_string(r.grids.size()) + " grids, " + std::to_string(points) +
                        " points, error bar (95%) at most " + fixedNumber(100.0 * maxRelative, 2) +
                        "% of each point's value, " + formatDuration(r.seconds) +
                        (short_.empty() ? std::string() : " (target not reached: " + short_ + ")"));
    }
    return lines;
}

}  // namespace lucerna::cli
