#pragma once
// The round values a false-colour legend labels, one rule for every legend drawn (the window's
// viewport, plan, compare and annual views; the report's plans and lux view), so that a legend
// reads 500 / 550 / 600 / 650 / 700 lx rather than 483.2 / 530.7 / 583 / 640.3 / 703.4.
// Pure functions: no painter, no widget.

#include <QString>

#include <vector>

namespace lucerna {

// How a legend maps values to its colours: evenly in the value, evenly in its logarithm, or in
// discrete bands between round values (as DIALux draws its result plans).
enum class LegendScale { Linear, Logarithmic, Bands };

// The legend's tick values in [lo, hi], ascending, 3 to 8 of them (fewer only where no round
// value lies in a degenerate range):
// - Linear: the multiples of a round step (1, 2 or 5 times a power of ten) that lie in the range.
// - Logarithmic: the values 1, 2 and 5 times a power of ten that lie in it (only the powers of
//   ten where those would be more than 8). A range that holds fewer than 3 of them (a factor of
//   ten always holds 3; 1.01 .. 5 holds only 2 and 5), or one reaching 0 or below, takes the
//   linear ticks instead.
// - Bands: the band edges within the range (bandEdges).
// A range with hi <= lo (a uniform grid) takes the ticks of the round range around lo
// (roundRangeAround); non-finite ends give none.
std::vector<double> legendTicks(double lo, double hi, LegendScale scale);

// The edges of the colour bands over [lo, hi]: the linear ticks, or on a range over a factor of
// ten above 0 the logarithmic ones (1, 2, 5 per decade), widened by one step at either end
// where lo or hi is not itself a round value, so that every band lies between two round values.
// At least two edges (one band) for any finite range.
std::vector<double> bandEdges(double lo, double hi);

// The round range around `value` for a legend of a uniform quantity: from the round number at or
// below 0.8 value to the one at or above 1.25 value (0 to 1 for 0, mirrored for negatives).
struct TickRange {
    double lo = 0, hi = 1;
};
TickRange roundRangeAround(double value);

// True when `value` is d x 10^k with d in {1, 2, 5} (up to rounding, relative 1e-9).
bool isRoundValue(double value);

// A tick's label: the shortest plain form ("500", "0.02", "1500"), an exponent past 1e6 or
// under 1e-4 ("2e+07").
QString tickText(double value);

}  // namespace lucerna
