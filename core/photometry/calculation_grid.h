#pragma once
// Calculation grids (EN 12464-1:2021, section 5.4 and annex): the points on a work plane, a wall
// or the floor where illuminance is computed and checked against a standard, and the figures a
// lighting designer reads off them.
//
// A grid is a rectangle given by a corner and two perpendicular edges (scene units). Its points
// are the centres of an nu x nv array of equal cells (so the outer points lie half a cell from
// the edges), with nu = ceil(|u| / p) and nv = ceil(|v| / p) for the spacing p: EN 12464-1's
// p = 0.2 * 5^log10(d) metres (d the longer side in metres, p at most 10 m) unless given. The
// illuminance is the one on the side the normal cross(u, v) faces.

#include "core/math.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct CalculationGrid {
    std::string name = "grid";
    V3d corner{0, 0, 0};
    V3d edgeU{1, 0, 0};   // scene units
    V3d edgeV{0, 0, 1};   // scene units, perpendicular to edgeU
    std::optional<double> spacingMeters;  // absent: EN 12464-1's rule

    // Unit normal cross(u, v) / |cross(u, v)|: the side whose illuminance is computed.
    V3d normal() const;
};

// The work plane of a room whose geometry spans [lo, hi] (scene units, y up): the extent in x and
// z less a border (EN 12464-1 leaves out a band along the walls, 0.5 m unless stated), at a
// height above the lowest geometry, facing up. Throws std::invalid_argument (one line) when the
// border leaves nothing.
CalculationGrid workPlaneGrid(const V3d& lo, const V3d& hi, double metersPerUnit, double heightMeters,
                              double borderMeters);

// The rectangle a user draws by clicking two corners on a surface (a, with its unit normal
// facing the viewer, and b), as the grid of the plane through a: on a floor, a table or a
// ceiling (|normal.y| >= 0.7) the rectangle spans x and z between the corners, lifted off the
// surface along its normal by offsetMeters (a work plane over the floor); on a wall it spans the
// wall's horizontal direction and y between the corners, offsetMeters in front of the wall. The
// grid faces the viewer's side. A zero extent gives a grid that layoutGrid rejects.
CalculationGrid gridFromCorners(const V3d& a, const V3d& normalAtA, const V3d& b, double metersPerUnit,
                                double offsetMeters);

// EN 12464-1's maximum grid spacing for a longest side of dMeters: 0.2 * 5^log10(d), at most 10 m.
double en12464Spacing(double dMeters);

struct GridLayout {
    int nu = 0, nv = 0;              // points along u and v
    double spacingUMeters = 0, spacingVMeters = 0;  // the actual cell sizes
    std::vector<V3d> points;         // row-major: index = j * nu + i, i along u (scene units)
};

// The points of a grid. Throws std::invalid_argument (one line) for a degenerate rectangle, edges
// that are not perpendicular, a non-positive spacing or more than maxPoints points.
GridLayout layoutGrid(const CalculationGrid& grid, double metersPerUnit, int maxPoints = 100000);

// The figures of EN 12464-1 over the grid's point values (lux), leaving out the points marked in
// `excluded` (non-zero: inside closed geometry, where no work is done and a 0 would only pull Emin
// and U0 to 0; empty: none left out). `weights` (empty: equal) weigh the points in Eavg: the
// areas of their cells, for points of several grids of different spacing (a room's walls).
struct GridStatistics {
    double average = 0, minimum = 0, maximum = 0;
    double uniformity = 0;  // U0 = Emin / Eavg (0 when Eavg is 0)
    int counted = 0;        // points in the figures
    int excluded = 0;       // points left out
};
GridStatistics gridStatistics(const std::vector<double>& lux, const std::vector<uint8_t>& excluded = {},
                              const std::vector<double>& weights = {});

// The grid as CSV: a header line, then one row per point: i, j, x, y, z (scene units), the
// illuminance in lux, its error bar in lux ("unknown" where the method cannot back one) and
// inside_geometry (1 for a point left out of the figures, else 0); with dfPerLux (100 / Eh,sky
// of a daylight-factor grid), also daylight_factor_percent and error_percent.
std::string gridCsv(const GridLayout& layout, const std::vector<double>& lux, const std::vector<double>& errorLux,
                    const std::vector<uint8_t>& insideGeometry = {}, bool errorUnknown = false,
                    std::optional<double> dfPerLux = std::nullopt);

}  // namespace lucerna
