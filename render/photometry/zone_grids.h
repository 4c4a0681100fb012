#pragma once
// A task area's surrounding zone and background area (README, "Task areas";
// core/photometry/surrounding_zones.h) as points computed with the task area's own, and their
// figures and checks as text.

#include "core/photometry/lighting_standards.h"
#include "core/photometry/surrounding_zones.h"
#include "render/photometry/grid_calculation.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

// A task area's zones computed in the task area's own calculation (`lucerna grid --task-area`
// and the Calculation grid dock): their points go after its points, so that they share its
// passes and its error target, and the result is then split.
class ZoneGrids {
public:
    ZoneGrids() = default;
    // The zones `area` has (none: empty), laid out in the box [lo, hi] (scene units) after
    // `taskPoints` points of the area's own; the requirements follow the activity's Em (none
    // without one). Throws std::invalid_argument (one line) where a band cannot be laid out.
    ZoneGrids(const TaskArea& area, const ActivityRequirement* activity, double metersPerUnit, const V3d& lo,
              const V3d& hi, size_t taskPoints);

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

}  // namespace lucerna
