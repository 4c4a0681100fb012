#include "core/photometry/calculation_grid.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace lucerna {

V3d CalculationGrid::normal() const { return edgeU.cross(edgeV).normalized(); }

CalculationGrid workPlaneGrid(const V3d& lo, const V3d& hi, double metersPerUnit, double heightMeters,
                              double borderMeters) {
    const double border = borderMeters / metersPerUnit;
    const double x0 = lo.x + border, x1 = hi.x - border, z0 = lo.z + border, z1 = hi.z - border;
    if (!(x1 > x0) || !(z1 > z0))
        throw std::invalid_argument("the scene is too small for a border of " + std::to_string(borderMeters) + " m");
    CalculationGrid g;
    g.name = "work plane";
    g.corner = V3d(x0, lo.y + heightMeters / metersPerUnit, z1);
    g.edgeU = V3d(x1 - x0, 0, 0);
    g.edgeV = V3d(0, 0, z0 - z1);  // cross(u, v) = +y
    return g;
}

CalculationGrid gridFromCorners(const V3d& a, const V3d& normalAtA, const V3d& b, double metersPerUnit,
                                double offsetMeters) {
    const double offset = offsetMeters / metersPerUnit;
    CalculationGrid g;
    g.name = "drawn rectangle";
    if (std::abs(normalAtA.y) >= 0.7) {
        const double x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x);
        const double z0 = std::min(a.z, b.z), z1 = std::max(a.z, b.z);
        if (normalAtA.y > 0) {  // a floor or a table: facing up
            g.corner = V3d(x0, a.y + offset, z1);
            g.edgeU = V3d(x1 - x0, 0, 0);
            g.edgeV = V3d(0, 0, z0 - z1);
        } else {  // a ceiling: facing down
            g.corner = V3d(x0, a.y - offset, z0);
            g.edgeU = V3d(x1 - x0, 0, 0);
            g.edgeV = V3d(0, 0, z1 - z0);
        }
        return g;
    }
    // A wall: h its horizontal normal toward the viewer; u runs to the viewer's right along the
    // wall (r = cross(-h, y)), v up, so cross(u, v) = h.
    const V3d h = V3d(normalAtA.x, 0, normalAtA.z).normalized();
    const V3d r(h.z, 0, -h.x);
    const double ra = a.dot(r), rb = b.dot(r);
    const double r0 = std::min(ra, rb), r1 = std::max(ra, rb);
    const double y0 = std::min(a.y, b.y), y1 = std::max(a.y, b.y);
    g.corner = a + h * offset + r * (r0 - ra) + V3d(0, y0 - a.y, 0);
    g.edgeU = r * (r1 - r0);
    g.edgeV = V3d(0, y1 - y0, 0);
    return g;
}

double en12464Spacing(double dMeters) { return std::min(10.0, 0.2 * std::pow(5.0, std::log10(dMeters))); }

GridLayout layoutGrid(const CalculationGrid& grid, double metersPerUnit, int maxPoints) {
    const double lu = grid.edgeU.length(), lv = grid.edgeV.length();
    if (!(lu > 0) || !(lv > 0) || !std::isfinite(lu) || !std::isfinite(lv))
        throw std::invalid_argument("grid '" + grid.name + "': its edges must have a positive, finite length");
    if (std::abs(grid.edgeU.dot(grid.edgeV)) > 1e-6 * lu * lv)
        throw std::invalid_argument("grid '" + grid.name + "': its edges must be perpendicular");
    const double luM = lu * metersPerUnit, lvM = lv * metersPerUnit;
    const double p = grid.spacingMeters ? *grid.spacingMeters : en12464Spacing(std::max(luM, lvM));
    if (!(p > 0) || !std::isfinite(p))
        throw std::invalid_argument("grid '" + grid.name + "': the spacing must be positive");
    // A side shorter than the spacing still gets one point, at its middle.
    const double nuD = std::max(1.0, std::ceil(luM / p - 1e-9)), nvD = std::max(1.0, std::ceil(lvM / p - 1e-9));
    if (nuD * nvD > double(maxPoints))
        throw std::invalid_argument("grid '" + grid.name + "': " + std::to_string(int64_t(nuD * nvD)) +
                                    " points is more than " + std::to_string(maxPoints));
    GridLayout g;
    g.nu = int(nuD);
    g.nv = int(nvD);
    g.spacingUMeters = luM / g.nu;
    g.spacingVMeters = lvM / g.nv;
    g.points.reserve(size_t(g.nu) * size_t(g.nv));
    for (int j = 0; j < g.nv; ++j)
        for (int i = 0; i < g.nu; ++i)
            g.points.push_back(grid.corner + grid.edgeU * ((i + 0.5) / g.nu) + grid.edgeV * ((j + 0.5) / g.nv));
    return g;
}

GridStatistics gridStatistics(const std::vector<double>& lux, const std::vector<uint8_t>& excluded,
                              const std::vector<double>& weights) {
    GridStatistics s;
    double sum = 0, weightSum = 0;
    for (size_t i = 0; i < lux.size(); ++i) {
        if (i < excluded.size() && excluded[i]) {
            ++s.excluded;
            continue;
        }
        s.minimum = s.counted == 0 ? lux[i] : std::min(s.minimum, lux[i]);
        s.maximum = s.counted == 0 ? lux[i] : std::max(s.maximum, lux[i]);
        const double w = i < weights.size() ? weights[i] : 1.0;
        sum += w * lux[i];
        weightSum += w;
        ++s.counted;
    }
    if (s.counted == 0 || !(weightSum > 0)) return s;
    s.average = sum / weightSum;
    s.uniformity = s.average > 0 ? s.minimum / s.average : 0.0;
    return s;
}

std::string gridCsv(const GridLayout& layout, const std::vector<double>& lux, const std::vector<double>& errorLux,
                    const std::vector<uint8_t>& insideGeometry, bool errorUnknown, std::optional<double> dfPerLux) {
    std::ostringstream out;
    out.precision(9);
    out << "i,j,x,y,z,illuminance_lux,error_lux,inside_geometry" << (dfPerLux ? ",daylight_factor_percent,error_percent" : "")
        << "\n";
    for (int j = 0; j < layout.nv; ++j)
        for (int i = 0; i < layout.nu; ++i) {
            const size_t k = size_t(j) * size_t(layout.nu) + size_t(i);
            const V3d& p = layout.points[k];
            out << i << ',' << j << ',' << p.x << ',' << p.y << ',' << p.z << ',' << (k < lux.size() ? lux[k] : 0.0)
                << ',';
            if (errorUnknown) out << "unknown";
            else out << (k < errorLux.size() ? errorLux[k] : 0.0);
            out << ',' << (k < insideGeometry.size() && insideGeometry[k] ? 1 : 0);
            if (dfPerLux) {
                out << ',' << (k < lux.size() ? lux[k] : 0.0) * *dfPerLux << ',';
                if (errorUnknown) out << "unknown";
                else out << (k < errorLux.size() ? errorLux[k] : 0.0) * *dfPerLux;
            }
            out << '\n';
        }
    return out.str();
}

}  // namespace lucerna
