#include "render/display/plan_scales.h"

#include "render/display/iso_lines.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

PlanScale planScale(const GridStatistics& s) {
    PlanScale out;
    if (s.minimum > 0 && s.maximum > 10 * s.minimum) {
        out.logScale = true;
        const double decade = std::pow(10.0, std::floor(std::log10(s.minimum)));
        out.lo = decade;
        for (double m : {2.0, 5.0})
            if (m * decade <= s.minimum) out.lo = m * decade;
        out.hi = out.lo;
        for (double d = decade; out.hi < s.maximum; d *= 10)
            for (double m : {1.0, 2.0, 5.0}) {
                const double level = m * d;
                if (level > s.minimum && level < s.maximum) out.levels.push_back(level);
                if (level >= s.maximum && out.hi < s.maximum) out.hi = level;
            }
        return out;
    }
    const std::vector<double> levels = isoLevels(s.minimum, s.maximum);
    if (levels.size() >= 2) {
        const double step = levels[1] - levels[0];
        out.lo = std::floor(s.minimum / step) * step;
        out.hi = std::ceil(s.maximum / step) * step;
        if (out.hi <= out.lo) out.hi = out.lo + step;
    } else {
        out.lo = std::max(0.0, s.minimum * 0.9);
        out.hi = std::max(s.maximum * 1.1, out.lo + 1);
    }
    out.levels = levels;
    return out;
}

PlanScale requirementScale(double requiredLux, const GridStatistics& s) {
    PlanScale out = planScale(s);
    if (!(requiredLux > 0)) return out;
    if (out.logScale) out.lo = requiredLux / 5, out.hi = requiredLux * 5;
    else out.lo = 0, out.hi = 2 * requiredLux;
    return out;
}

double scaleBarMeters(double pixelsPerMeter, double maxPixels) {
    if (!(pixelsPerMeter > 0) || !(maxPixels > 0)) return 0;
    double meters = std::pow(10.0, std::floor(std::log10(maxPixels / pixelsPerMeter)));
    for (double m : {5.0, 2.0})
        if (meters * m * pixelsPerMeter <= maxPixels) return meters * m;
    return meters;
}

}  // namespace lucerna
