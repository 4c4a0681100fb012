#pragma once
// A grid's results as text, written here once for every place that shows them: `lucerna grid`
// (app/grid_command.cpp), the report's pages and the summary `lucerna report` prints
// (report/, app/report_command.cpp) and the calculation dock (ui/calculation/grid_panel.cpp), so
// that a reader (or a test) finds the same figures in each. Durations read as
// core/number_format.h's formatDuration writes them.

#include "core/photometry/calculation_grid.h"
#include "render/photometry/grid_calculation.h"

#include <string>
#include <vector>

namespace lucerna {

// "Eavg 512.3 lx, Emin 301.0 lx, Emax 702.4 lx, U0 0.588"; when every point is inside
// geometry, "Eavg, Emin, Emax, U0: none (every point is inside geometry)".
std::string gridFiguresLine(const GridStatistics& s);

// The same of a daylight-factor grid (its values in %): "DFavg 2.41%, DFmin 1.02%, DFmax 5.60%,
// uniformity DFmin/DFavg 0.423", or "DF: none (every point is inside geometry)".
std::string daylightFactorFiguresLine(const GridStatistics& s);

// "4 of 64 points inside geometry, excluded from Eavg, Emin, Emax and U0" (of a daylight-factor
// grid, "... excluded"); empty when no point is.
std::string excludedPointsLine(const GridStatistics& s, size_t points, bool daylightFactor = false);

// The error bar after the passes, in one line: "error bar (95%) at most 1.93% of each point's
// value after 12 passes, 192 samples per point, 3.2 s" (and " (target not reached)"). When the
// method cannot carry the light that reaches some of the `counted` points through glass, two:
// "path cannot carry light through glass to 4 of 64 points: use bdpt (or method auto)" and
// "error bar unknown (the light through glass is missing) after ...".
std::vector<std::string> gridErrorLines(const GridResult& r, int counted);

// Point k's value as a table shows it: "inside" for a point inside geometry, else its lux times
// `scale` to `decimals` places ("%.1f" of the lux by default).
std::string gridPointText(const GridResult& r, size_t k, double scale = 1.0, int decimals = 1);

// The grid's values as a text table, rows from the far edge (v) down, each value (gridPointText)
// right-aligned in 9 characters, a line per row; empty for a grid more than 16 points wide,
// which reads better from the CSV.
std::string gridTableText(const GridLayout& layout, const GridResult& r, double scale = 1.0, int decimals = 1);

}  // namespace lucerna
