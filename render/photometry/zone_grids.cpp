#include "render/photometry/zone_grids.h"

#include "core/number_format.h"
#include "core/photometry/grid_error_bars.h"
#include "render/photometry/grid_text.h"

namespace lucerna {

namespace {

// Elements [begin, end) of a per-point vector (empty stays empty).
template <class T> std::vector<T> slice(const std::vector<T>& v, size_t begin, size_t end) {
    if (v.size() < end) return {};
    return std::vector<T>(v.begin() + std::ptrdiff_t(begin), v.begin() + std::ptrdiff_t(end));
}

GridResult part(const GridResult& all, size_t begin, size_t end) {
    GridResult r = all;
    r.lux = slice(all.lux, begin, end);
    r.errorLux = slice(all.errorLux, begin, end);
    r.insideGeometry = slice(all.insideGeometry, begin, end);
    return r;
}

}  // namespace

ZoneGrids::ZoneGrids(const TaskArea& area, const ActivityRequirement* activity, double metersPerUnit,
                     const V3d& lo, const V3d& hi, size_t taskPoints)
    : taskPoints_(taskPoints) {
    const TaskAreaZones zones = taskAreaZones(area, metersPerUnit, lo, hi);
    if (activity) taskEm_ = activity->maintainedLux;
    const auto add = [&](const char* name, double width, const ZoneGrid& grid, std::optional<ZoneRequirement> requirement) {
        Zone z{name, width, taskPoints_ + points_.size(), 0, requirement};
        points_.insert(points_.end(), grid.points.begin(), grid.points.end());
        z.end = taskPoints_ + points_.size();
        zones_.push_back(z);
    };
    std::optional<ZoneRequirement> surrounding;
    if (activity) surrounding = surroundingZoneRequirement(activity->maintainedLux);
    if (zones.surrounding) add("surrounding zone", *area.surroundingMeters, *zones.surrounding, surrounding);
    if (zones.background)
        add("background area", *area.backgroundMeters, *zones.background,
            surrounding ? std::optional(backgroundAreaRequirement(surrounding->maintainedLux)) : std::nullopt);
}

GridResult ZoneGrids::taskPart(const GridResult& all) const {
    return points_.empty() ? all : part(all, 0, taskPoints_);
}

std::vector<std::string> ZoneGrids::lines(const GridResult& all, bool maintainedValues) const {
    std::vector<std::string> out;
    for (const Zone& z : zones_) {
        const std::string head =
            z.name + " (" + shortestNumber(z.widthMeters) + " m, " + std::to_string(z.end - z.begin) + " points)";
        if (z.end == z.begin) {
            out.push_back(head + ": none (the room leaves no band)");
            continue;
        }
        const GridResult r = part(all, z.begin, z.end);
        if (r.lux.empty()) continue;  // no pass yet
        const GridStatistics s = gridStatistics(r.lux, r.insideGeometry);
        out.push_back(head + ": " + gridFiguresLine(s));
        if (!z.requirement) {
            out.push_back("  no activity: nothing to check");
            continue;
        }
        out.push_back("  required" +
                      std::string(taskEm_ ? " (EN 12464-1, task Em " + fixedNumber(*taskEm_, 0) + " lx)" : "") +
                      ": Em " + fixedNumber(z.requirement->maintainedLux, 0) + " lx, U0 " +
                      fixedNumber(z.requirement->uniformity, 2));
        if (s.counted == 0) continue;
        TaskAreaFigures figures;
        figures.grid = s;
        if (!r.errorBarUnknown) figures.gridErrors = gridErrorBars(s, r.lux, r.errorLux, r.insideGeometry);
        figures.maintainedValues = maintainedValues;
        for (const RequirementCheck& c : checkZone(*z.requirement, figures)) out.push_back("  " + c.describe());
    }
    return out;
}

}  // namespace lucerna
