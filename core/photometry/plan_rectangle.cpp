#include "core/photometry/plan_rectangle.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {
// A vector along x or z only (to a millionth of its length).
bool alongXOrZ(const V3d& e) {
    const double tol = 1e-6 * e.length();
    return std::abs(e.y) <= tol && (std::abs(e.x) <= tol || std::abs(e.z) <= tol);
}
}  // namespace

std::optional<PlanRectangle> planRectangle(const CalculationGrid& grid) {
    if (!alongXOrZ(grid.edgeU) || !alongXOrZ(grid.edgeV) || !(grid.edgeU.length() > 0) || !(grid.edgeV.length() > 0))
        return std::nullopt;
    const V3d far = grid.corner + grid.edgeU + grid.edgeV;
    PlanRectangle r;
    r.x0 = std::min(grid.corner.x, far.x);
    r.z0 = std::min(grid.corner.z, far.z);
    r.width = std::abs(far.x - grid.corner.x);
    r.depth = std::abs(far.z - grid.corner.z);
    r.y = grid.corner.y;
    if (!(r.width > 0) || !(r.depth > 0)) return std::nullopt;
    return r;
}

CalculationGrid gridOfPlanRectangle(const PlanRectangle& r, const CalculationGrid& like) {
    CalculationGrid g = like;
    g.corner = V3d(r.x0, r.y, r.z0 + r.depth);
    g.edgeU = V3d(r.width, 0, 0);
    g.edgeV = V3d(0, 0, -r.depth);  // cross(u, v) = +y
    return g;
}

}  // namespace lucerna
