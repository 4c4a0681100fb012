#pragma once
// A year's figures in words, one line each (SPEC.md section 6's lines, then the stated error),
// for `lucerna annual`, the Annual dock and the report, so that they say the same.

#include "core/daylight/annual_metrics.h"
#include "core/daylight/epw_file.h"
#include "render/annual/annual_calculation.h"

#include <string>
#include <vector>

namespace lucerna {

// The weather file's location, the hours, sDA, ASE, UDI and EN 17037's illuminance method.
std::vector<std::string> annualFigureLines(const WeatherFile& weather, const AnnualResult& r, const AnnualMetrics& m,
                                           const Occupancy& occupancy);
// The stated 95% error of the hourly values and its parts.
std::string annualErrorLine(const AnnualResult& r);

}  // namespace lucerna
