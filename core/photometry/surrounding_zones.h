#pragma once
// EN 12464-1's zones around a task area (2011: 4.3.2, 4.3.3 and table 1; README, "Task
// areas"): the immediate surrounding zone, a band at least 0.5 m wide around the task area, and
// the background area, a band at least 3 m wide around that zone within the limits of the room.
// Their requirements follow from the task area's Em; their points are those of the bands only
// (the task area's own points are not theirs).

#include "core/photometry/calculation_grid.h"
#include "core/photometry/lighting_standards.h"
#include "core/scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

// What a zone must achieve: its average at least maintainedLux (maintained, as a task area's
// Em), its U0 = Emin / Eavg at least uniformity.
struct ZoneRequirement {
    double maintainedLux = 0;
    double uniformity = 0;
};

// EN 12464-1's table 1: a task area of Em 750 lx or more asks 500 lx of its surrounding zone,
// 500 lx asks 300 lx, 300 lx asks 200 lx, and one of 200 lx or less the task's own Em (between
// the table's rows, the lower row's value, never more than the task's); U0 0.40.
ZoneRequirement surroundingZoneRequirement(double taskMaintainedLux);
// A third of the surrounding zone's Em; U0 0.10.
ZoneRequirement backgroundAreaRequirement(double surroundingMaintainedLux);

// The points of a band in a task area's plane: up to four rectangular strips (the two along u
// full length, the two along v between them), each a calculation grid facing as the task area
// does, so that every point lies in the band.
struct ZoneGrid {
    std::vector<CalculationGrid> strips;
    std::vector<V3d> points;   // the strips' points (layoutGrid's), strip after strip
    double spacingMeters = 0;  // of every strip
};

// The band between the task area's rectangle grown by insideMeters on each side and the same
// grown by insideMeters + widthMeters, clipped to the room: along u and along v, to the extent
// of the box [roomLo, roomHi] (scene units; exact for a rectangle with sides along the axes). The
// spacing is `spacingMeters` when given, else EN 12464-1's rule for the band's longer outer side.
// No strips where the room leaves nothing of the band. Throws std::invalid_argument (one line)
// for a degenerate task rectangle or too many points.
ZoneGrid zoneGrid(const CalculationGrid& task, double insideMeters, double widthMeters, double metersPerUnit,
                  const V3d& roomLo, const V3d& roomHi, std::optional<double> spacingMeters = std::nullopt);

// The band's outer rectangle, clipped to the room as zoneGrid clips it (the task area's name and
// spacing); nothing where the room leaves none of it.
std::optional<CalculationGrid> zoneOuterRectangle(const CalculationGrid& task, double insideMeters, double widthMeters,
                                                  double metersPerUnit, const V3d& roomLo, const V3d& roomHi);

// A task area's zones as its keys give them (surrounding_m, background_m; absent where not
// given), in the room [roomLo, roomHi], spaced as the task area is when it gives a spacing.
struct TaskAreaZones {
    std::optional<ZoneGrid> surrounding, background;
    bool empty() const { return !surrounding && !background; }
};
TaskAreaZones taskAreaZones(const TaskArea& area, double metersPerUnit, const V3d& roomLo, const V3d& roomHi);

// Em and U0 of a zone against its requirement, judged as checkRequirements judges a task area's
// (met, borderline within the error bar, not met; Em not checked without maintained values).
std::vector<RequirementCheck> checkZone(const ZoneRequirement& requirement, const TaskAreaFigures& figures);

// "surrounding zone (0.5 m): Em 300 lx, U0 0.40" and "background area (3 m): Em 100 lx, U0 0.10".
std::string describeZoneRequirement(const std::string& zone, double widthMeters, const ZoneRequirement& requirement);

}  // namespace lucerna
