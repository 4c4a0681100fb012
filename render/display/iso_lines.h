#pragma once
// Iso-lux lines over a calculation grid's point values, as a lighting designer reads them off a
// DIALux plan: round levels (1, 2 or 5 times a power of ten apart) and their contours by
// marching squares over the lattice of grid points. Pure functions, shared by the plan view
// (ui/plan/) and the report's plans (report/), and checked by tests without a window.

#include <vector>

namespace lucerna {

// Levels at a round step strictly between lo and hi, about `wanted` of them (fewer when the
// values are nearly uniform; none when hi <= lo).
std::vector<double> isoLevels(double lo, double hi, int wanted = 6);

// One piece of a contour, in lattice coordinates: (i, j) is point i along u, j along v; the ends
// lie on the lattice's edges, at the linear interpolation of the values.
struct IsoSegment {
    double i0, j0, i1, j1;
    double level;
};

// The contours of `values` (row-major, index j * nu + i) at each level. A saddle cell is resolved
// by its mean value.
std::vector<IsoSegment> isoSegments(const std::vector<double>& values, int nu, int nv, const std::vector<double>& levels);

}  // namespace lucerna
