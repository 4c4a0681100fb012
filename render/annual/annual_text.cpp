#include "render/annual/annual_text.h"

#include <cstdio>

namespace lucerna {

namespace {

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f%%", 100 * fraction);
    return text;
}

template <class... Args>
std::string format(const char* pattern, Args... args) {
    char text[512];
    std::snprintf(text, sizeof text, pattern, args...);
    return text;
}

}  // namespace

std::vector<std::string> annualFigureLines(const WeatherFile& weather, const AnnualResult& r, const AnnualMetrics& m,
                                           const Occupancy& occupancy) {
    std::vector<std::string> lines;
    lines.push_back(format("weather: %s; %d hours with missing values", weather.describe().c_str(), weather.hoursWithMissingValues));
    lines.push_back(format("hours: %d with daylight (Ib > 0 or Ed > 0), %d occupied (%g:00 to %g:00 local standard time)",
                           r.daylightHours, m.occupiedHours, occupancy.fromHour, occupancy.toHour));
    lines.push_back(format("sDA300/50%%: %.1f%% of %d points have 300 lx or more in at least half of the occupied hours "
                           "(blinds are not modelled)",
                           m.sda300, m.countedPoints));
    lines.push_back(format("ASE1000,250h: %.1f%% of the points get more than 1000 lx of direct sun in more than 250 occupied hours",
                           m.ase));
    lines.push_back(format("UDI: fell short (< 100 lx) %s, useful (100 to 3000 lx) %s, exceeded (> 3000 lx) %s of the "
                           "occupied hours, means over the points",
                           percent(m.udiFellShort).c_str(), percent(m.udiUseful).c_str(), percent(m.udiExceeded).c_str()));
    std::string en = "EN 17037 illuminance method, over " + std::to_string(m.daylightHours) + " daylight hours:";
    for (const En17037Level& level : m.en17037)
        en += format(" %s %s (%g lx on 50%% of the plane in %s of the hours, %g lx on 95%% in %s);", level.name.c_str(),
                     level.met ? "met" : "not met", level.targetLux, percent(level.fractionTarget).c_str(),
                     level.minimumTargetLux, percent(level.fractionMinimum).c_str());
    en.pop_back();
    lines.push_back(en);
    return lines;
}

std::string annualErrorLine(const AnnualResult& r) {
    return format("stated 95%% error of the hourly values: statistical %s of the value (median), sky and sun discretisation "
                  "%s (measured on a sample of points and hours: straight view %s, reflected sky %s, sun's reflections %s)",
                  percent(r.statisticalRelative).c_str(), percent(r.discretisationRelative).c_str(),
                  percent(r.discretisationParts[0]).c_str(), percent(r.discretisationParts[1]).c_str(),
                  percent(r.discretisationParts[2]).c_str());
}

}  // namespace lucerna
