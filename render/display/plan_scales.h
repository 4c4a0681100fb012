#pragma once
// The two scales a plan carries, one rule each for every plan drawn (the window's plan view, the
// report's plan figures): the false-colour legend of its grid's values, with the iso-lux levels
// on it, and the length of its scale bar.

#include "core/photometry/calculation_grid.h"
#include "render/display/false_colour.h"

#include <QString>

#include <optional>
#include <vector>

namespace lucerna {

// The legend's range and the levels of the iso-lux lines for an area's values: linear, from a
// round number at or below Emin to one at or above Emax, in steps of the iso levels'; or, where
// Emax is more than ten times Emin (a sun patch, a spotlit table), logarithmic, with levels at 1,
// 2 and 5 times the powers of ten between them, so that the dim part of the area reads too.
struct PlanScale {
    double lo = 0, hi = 1;
    bool logScale = false;
    std::vector<double> levels;

    // The legend of this scale; `scale` given: on that scale instead of the plan's own.
    Legend legend(const QString& unit, std::optional<LegendScale> scale = std::nullopt) const {
        return scale ? makeLegend(lo, hi, *scale, unit) : Legend{lo, hi, logScale, unit};
    }
};
PlanScale planScale(const GridStatistics& statistics);

// The scale of a task area's plan centred on its requirement, so that the requirement reads in
// the middle of the ramp and compliant area is not saturated: linear from 0 to 2 Em; or, where
// planScale would go logarithmic (Emax over ten times Emin), logarithmic from Em / 5 to 5 Em.
// The iso-lux levels stay planScale's, which follow the values. Em in lx, above 0.
PlanScale requirementScale(double requiredLux, const GridStatistics& statistics);

// The scale bar's length in metres: the longest round length (1, 2 or 5 times a power of ten)
// no longer than `maxPixels` at `pixelsPerMeter`.
double scaleBarMeters(double pixelsPerMeter, double maxPixels);

}  // namespace lucerna
