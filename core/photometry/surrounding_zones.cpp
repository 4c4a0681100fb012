#include "core/photometry/surrounding_zones.h"

#include "core/number_format.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucerna {

ZoneRequirement surroundingZoneRequirement(double taskMaintainedLux) {
    const double e = taskMaintainedLux;
    const double lux = e >= 750 ? 500 : e >= 500 ? 300 : e >= 300 ? 200 : std::min(e, 200.0);
    return {lux, 0.40};
}

ZoneRequirement backgroundAreaRequirement(double surroundingMaintainedLux) { return {surroundingMaintainedLux / 3, 0.10}; }

namespace {
// A band in the task area's frame: s along u, t along v, from its corner (scene units).
struct Band {
    V3d unitU, unitV;
    double lengthU = 0, lengthV = 0;
    double s0 = 0, s1 = 0, t0 = 0, t1 = 0;  // the outer rectangle, clipped to the room
    double a0 = 0, a1 = 0, b0 = 0, b1 = 0;  // the rectangle it leaves out
};

Band band(const CalculationGrid& task, double insideMeters, double widthMeters, double metersPerUnit, const V3d& roomLo,
          const V3d& roomHi) {
    Band b;
    b.lengthU = task.edgeU.length(), b.lengthV = task.edgeV.length();
    if (!(b.lengthU > 0) || !(b.lengthV > 0)) throw std::invalid_argument("the task area's rectangle is degenerate");
    b.unitU = task.edgeU / b.lengthU, b.unitV = task.edgeV / b.lengthV;
    // The room's extent along u and v.
    double roomS0 = 1e300, roomS1 = -1e300, roomT0 = 1e300, roomT1 = -1e300;
    for (int k = 0; k < 8; ++k) {
        const V3d p(k & 1 ? roomHi.x : roomLo.x, k & 2 ? roomHi.y : roomLo.y, k & 4 ? roomHi.z : roomLo.z);
        const double s = (p - task.corner).dot(b.unitU), t = (p - task.corner).dot(b.unitV);
        roomS0 = std::min(roomS0, s), roomS1 = std::max(roomS1, s), roomT0 = std::min(roomT0, t), roomT1 = std::max(roomT1, t);
    }
    const double inside = insideMeters / metersPerUnit, outside = (insideMeters + widthMeters) / metersPerUnit;
    b.s0 = std::max(-outside, roomS0), b.s1 = std::min(b.lengthU + outside, roomS1);
    b.t0 = std::max(-outside, roomT0), b.t1 = std::min(b.lengthV + outside, roomT1);
    b.a0 = -inside, b.a1 = b.lengthU + inside, b.b0 = -inside, b.b1 = b.lengthV + inside;
    return b;
}

CalculationGrid rectangle(const CalculationGrid& task, const Band& b, double sa, double sb, double ta, double tb) {
    CalculationGrid g;
    g.name = task.name;
    g.corner = task.corner + b.unitU * sa + b.unitV * ta;
    g.edgeU = b.unitU * (sb - sa);
    g.edgeV = b.unitV * (tb - ta);
    g.spacingMeters = task.spacingMeters;
    return g;
}
}  // namespace

ZoneGrid zoneGrid(const CalculationGrid& task, double insideMeters, double widthMeters, double metersPerUnit,
                  const V3d& roomLo, const V3d& roomHi, std::optional<double> spacingMeters) {
    const Band b = band(task, insideMeters, widthMeters, metersPerUnit, roomLo, roomHi);
    ZoneGrid zone;
    const double longer = std::max(b.s1 - b.s0, b.t1 - b.t0) * metersPerUnit;
    zone.spacingMeters = spacingMeters ? *spacingMeters : en12464Spacing(std::max(longer, 1e-9));
    // A strip narrower than this is an edge of the room, not a band.
    const double tiny = 1e-9 * (b.lengthU + b.lengthV + (insideMeters + widthMeters) / metersPerUnit);
    const auto strip = [&](double sa, double sb, double ta, double tb) {
        if (!(sb - sa > tiny) || !(tb - ta > tiny)) return;
        CalculationGrid g = rectangle(task, b, sa, sb, ta, tb);
        g.spacingMeters = zone.spacingMeters;
        const GridLayout layout = layoutGrid(g, metersPerUnit);
        zone.points.insert(zone.points.end(), layout.points.begin(), layout.points.end());
        zone.strips.push_back(g);
    };
    const double tv0 = std::max(b.t0, b.b0), tv1 = std::min(b.t1, b.b1);  // the v strips' extent
    strip(b.s0, b.s1, b.t0, std::min(b.b0, b.t1));   // along u, low v
    strip(b.s0, b.s1, std::max(b.b1, b.t0), b.t1);   // along u, high v
    strip(b.s0, std::min(b.a0, b.s1), tv0, tv1);     // along v, low u
    strip(std::max(b.a1, b.s0), b.s1, tv0, tv1);     // along v, high u
    return zone;
}

std::optional<CalculationGrid> zoneOuterRectangle(const CalculationGrid& task, double insideMeters, double widthMeters,
                                                  double metersPerUnit, const V3d& roomLo, const V3d& roomHi) {
    const Band b = band(task, insideMeters, widthMeters, metersPerUnit, roomLo, roomHi);
    if (!(b.s1 > b.s0) || !(b.t1 > b.t0)) return std::nullopt;
    return rectangle(task, b, b.s0, b.s1, b.t0, b.t1);
}

TaskAreaZones taskAreaZones(const TaskArea& area, double metersPerUnit, const V3d& roomLo, const V3d& roomHi) {
    TaskAreaZones zones;
    if (!area.surroundingMeters) return zones;
    zones.surrounding = zoneGrid(area.grid, 0, *area.surroundingMeters, metersPerUnit, roomLo, roomHi, area.grid.spacingMeters);
    if (area.backgroundMeters)
        zones.background = zoneGrid(area.grid, *area.surroundingMeters, *area.backgroundMeters, metersPerUnit, roomLo,
                                    roomHi, area.grid.spacingMeters);
    return zones;
}

std::vector<RequirementCheck> checkZone(const ZoneRequirement& requirement, const TaskAreaFigures& figures) {
    // A zone has no UGR or Ra of its own: the task area's checks, Em and U0 only.
    const ActivityRequirement asActivity{"", "", "", requirement.maintainedLux, 0, requirement.uniformity, 0};
    std::vector<RequirementCheck> checks = checkRequirements(asActivity, figures);
    checks.resize(2);
    return checks;
}

std::string describeZoneRequirement(const std::string& zone, double widthMeters, const ZoneRequirement& requirement) {
    return zone + " (" + shortestNumber(widthMeters) + " m): Em " + fixedNumber(requirement.maintainedLux, 0) +
           " lx, U0 " + fixedNumber(requirement.uniformity, 2);
}

}  // namespace lucerna
