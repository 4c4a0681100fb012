#pragma once
// A task area's surrounding zone and background area computed with it in the Calculation grid
// dock (README, "Task areas"; core/photometry/surrounding_zones.h): their points go after the
// task area's own in one calculation, so that they share its passes and its error target; the
// result is then split, the task area's part shown as ever and each zone's figures (Eavg, Emin,
// Emax, U0) and checks against its derived requirement written under them.

#include "core/photometry/surrounding_zones.h"
#include "render/photometry/grid_calculation.h"

#include <string>
#include <vector>

namespace lucerna {

class ZoneFigures {
public:
    ZoneFigures() = default;
    // The zones `area` has (none: empty), laid out in `scene`'s room after `taskPoints` points of
    // the task area's own. Throws std::invalid_argument (one line) where a band cannot be laid out.
    ZoneFigures(const TaskArea& area, const Scene& scene, size_t taskPoints);

    bool empty() const { return zones_.empty(); }
    // The zones' points, to compute after the task area's.
    const std::vector<V3d>& points() const { return points_; }
    // The task area's own part of a result over all the points.
    GridResult taskPart(const GridResult& all) const;
    // Per zone: its figures, its requirement (from the activity's Em; none without an activity)
    // and the checks, as the task area's are judged (maintainedValues: Em may be checked).
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
