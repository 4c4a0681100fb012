#pragma once
// 95% error bars of a grid's figures (Eavg, Emin, U0), from the points' own, so that a check
// against a requirement can tell met from borderline (core/photometry/lighting_standards.h).

#include "core/photometry/calculation_grid.h"

#include <cstdint>
#include <vector>

namespace lucerna {

// In the figures' units. Eavg's bar is the mean of the points' bars: a bound whatever the
// correlation between points (VPL and MLT estimates share their samples). Emin's is the bar of the
// point that is the minimum; U0's adds their relative bars (a first-order bound).
struct GridErrorBars {
    double average = 0, minimum = 0, uniformity = 0;
};

// `stats`: gridStatistics(lux, excluded); `errorLux`: one 95% bar per point, as `lux`; points
// marked in `excluded` are left out, and `weights` weigh Eavg's bar, as gridStatistics does.
GridErrorBars gridErrorBars(const GridStatistics& stats, const std::vector<double>& lux,
                            const std::vector<double>& errorLux, const std::vector<uint8_t>& excluded = {},
                            const std::vector<double>& weights = {});

}  // namespace lucerna
