#pragma once
// What `lucerna grid --task-area` adds to a task area's grid (README, "Task areas"): its
// surrounding zone and background area, computed with it, and EN 12464-1:2021's figures (Ez over
// the area, the room's walls and ceiling; render/photometry/task_area_figures.h), computed after
// it, with the checks of all of them in the command's words.

#include "core/photometry/surrounding_zones.h"
#include "render/photometry/task_area_figures.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna::cli {

// A task area's zones computed in the task area's own calculation: their points go after its
// points, so that they share its passes and its error target (as the Calculation grid dock
// computes them), and the result is then split.
class GridZones {
public:
    GridZones() = default;
    // The zones `area` has (none: empty), laid out in `room` (the box the area lies in) after
    // `taskPoints` points of the area's own; the requirements follow the activity's Em (none
    // without one). Throws std::invalid_argument (one line) where a band cannot be laid out.
    GridZones(const TaskArea& area, const ActivityRequirement* activity, double metersPerUnit, const TaskAreaRoom& room,
              size_t taskPoints);

    bool empty() const { return zones_.empty(); }
    // The zones' points, to compute after the task area's.
    const std::vector<V3d>& points() const { return points_; }
    // The task area's own part of a result over all the points.
    GridResult taskPart(const GridResult& all) const;
    // Per zone: "surrounding zone (0.5 m, 40 points): Eavg ...", its requirement and its Em and
    // U0 checks (maintainedValues: Em may be checked), or "  no activity: nothing to check".
    std::vector<std::string> lines(const GridResult& all, bool maintainedValues) const;

private:
    struct Zone {
        std::string name;
        double widthMeters = 0;
        size_t begin = 0, end = 0;  // its points in the result
        std::optional<ZoneRequirement> requirement;
    };
    std::vector<Zone> zones_;
    std::vector<V3d> points_;
    size_t taskPoints_ = 0;
    std::optional<double> taskEm_;  // the activity's Em, lx
};

// The 2021 figures to compute: what the requirement asks for (extrasFor), with --cylindrical
// and --room-surfaces added whether it asks or not, nothing with --horizontal-only.
TaskAreaExtrasRequest requestedExtras(const ActivityRequirement* requirement, bool cylindrical, bool roomSurfaces,
                                      bool horizontalOnly);

// The lines of what was computed: describeExtras' (Ez, the modelling ratio against `horizontal`,
// walls, ceiling), then how far each calculation got ("Ez: error bar (95%) at most ...",
// "room surfaces: 5 grids, 180 points, ...").
std::vector<std::string> extrasLines(const TaskAreaExtras& extras, const GridStatistics& horizontal);

}  // namespace lucerna::cli
