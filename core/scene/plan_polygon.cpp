#include "core/scene/plan_polygon.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lucerna {

namespace {

double cross(const V2d& a, const V2d& b) { return a.x * b.y - a.y * b.x; }

// Areas below this count as zero: a millionth of a part per million of the polygon's extent
// squared, so that corners typed to the millimetre on a straight wall count as on it.
double areaTolerance(const PlanPolygon& p) {
    V2d lo(1e300, 1e300), hi(-1e300, -1e300);
    for (const V2d& v : p) lo = V2d(std::min(lo.x, v.x), std::min(lo.y, v.y)), hi = V2d(std::max(hi.x, v.x), std::max(hi.y, v.y));
    const double extent = p.empty() ? 0 : (hi - lo).length();
    return 1e-12 * std::max(extent * extent, 1e-300);
}

// The side of line ab that c lies on: 1 left, -1 right, 0 on it (within `eps`, an area).
int orientation(const V2d& a, const V2d& b, const V2d& c, double eps) {
    const double v = cross(b - a, c - a);
    return v > eps ? 1 : v < -eps ? -1 : 0;
}

// p, collinear with ab, lies within the segment.
bool withinSegment(const V2d& a, const V2d& b, const V2d& p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

// Closed segments ab and cd share a point.
bool segmentsTouch(const V2d& a, const V2d& b, const V2d& c, const V2d& d, double eps) {
    const int o1 = orientation(a, b, c, eps), o2 = orientation(a, b, d, eps);
    const int o3 = orientation(c, d, a, eps), o4 = orientation(c, d, b, eps);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && withinSegment(a, b, c)) || (o2 == 0 && withinSegment(a, b, d)) ||
           (o3 == 0 && withinSegment(c, d, a)) || (o4 == 0 && withinSegment(c, d, b));
}

// p inside or on the counter-clockwise triangle abc.
bool inTriangle(const V2d& p, const V2d& a, const V2d& b, const V2d& c, double eps) {
    return orientation(a, b, p, eps) >= 0 && orientation(b, c, p, eps) >= 0 && orientation(c, a, p, eps) >= 0;
}

std::string wall(size_t edge) { return std::to_string(edge + 1); }

}  // namespace

double signedArea(const PlanPolygon& p) {
    double twice = 0;
    for (size_t i = 0; i < p.size(); ++i) twice += cross(p[i], p[(i + 1) % p.size()]);
    return 0.5 * twice;
}

std::optional<std::string> outlineProblem(const PlanPolygon& p) {
    const size_t n = p.size();
    if (n < 3) return "an outline needs at least 3 corners, got " + std::to_string(n);
    for (const V2d& v : p)
        if (!std::isfinite(v.x) || !std::isfinite(v.y)) return std::string("a corner is not a finite number");
    const double eps = areaTolerance(p);
    for (size_t i = 0; i < n; ++i)
        if (p[i] == p[(i + 1) % n]) return "wall " + wall(i) + " has no length (corners " + std::to_string(i + 1) + " and " +
                                           std::to_string((i + 1) % n + 1) + " are the same point)";
    // Adjacent walls share a corner; they may run straight on but not double back over each other.
    for (size_t i = 0; i < n; ++i) {
        const V2d &a = p[i], &b = p[(i + 1) % n], &c = p[(i + 2) % n];
        if (orientation(a, b, c, eps) == 0 && (c - b).dot(a - b) > 0)
            return "walls " + wall(i) + " and " + wall((i + 1) % n) + " double back over each other";
    }
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // adjacent through the first corner
            if (segmentsTouch(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n], eps))
                return "the outline crosses itself: walls " + wall(i) + " and " + wall(j) + " meet";
        }
    if (std::abs(signedArea(p)) <= eps) return std::string("the outline encloses no area");
    return std::nullopt;
}

bool containsPoint(const PlanPolygon& p, const V2d& q) {
    const double eps = areaTolerance(p);
    bool inside = false;
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
        const V2d &a = p[j], &b = p[i];
        if (orientation(a, b, q, eps) == 0 && withinSegment(a, b, q)) return true;
        if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    }
    return inside;
}

bool polygonsOverlap(const PlanPolygon& a, const PlanPolygon& b) {
    if (a.empty() || b.empty()) return false;
    PlanPolygon both = a;
    both.insert(both.end(), b.begin(), b.end());
    const double eps = areaTolerance(both);
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = 0; j < b.size(); ++j)
            if (segmentsTouch(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()], eps)) return true;
    return containsPoint(b, a[0]) || containsPoint(a, b[0]);
}

std::vector<std::array<int, 3>> triangulate(const PlanPolygon& p) {
    std::vector<std::array<int, 3>> out;
    const int n = int(p.size());
    if (n < 3) return out;
    const bool clockwise = signedArea(p) < 0;
    const double eps = areaTolerance(p);
    // Worked on counter-clockwise; the triangles are turned back at the end.
    std::vector<int> left(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) left[size_t(i)] = clockwise ? n - 1 - i : i;
    while (left.size() > 3) {
        const size_t m = left.size();
        bool clipped = false;
        for (size_t k = 0; k < m && !clipped; ++k) {
            const int a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
            const int turn = orientation(p[size_t(a)], p[size_t(b)], p[size_t(c)], eps);
            if (turn < 0) continue;  // a reflex corner is no ear
            bool ear = true;
            if (turn > 0)
                for (int v : left) {
                    if (v == a || v == b || v == c) continue;
                    const V2d& q = p[size_t(v)];
                    if (q == p[size_t(a)] || q == p[size_t(b)] || q == p[size_t(c)]) continue;
                    if (inTriangle(q, p[size_t(a)], p[size_t(b)], p[size_t(c)], eps)) {
                        ear = false;
                        break;
                    }
                }
            if (!ear) continue;
            // A corner on a straight run is dropped without a triangle.
            if (turn > 0) out.push_back({a, b, c});
            left.erase(left.begin() + std::ptrdiff_t(k));
            clipped = true;
        }
        if (!clipped) throw std::logic_error("triangulate: the polygon is not simple");
    }
    if (orientation(p[size_t(left[0])], p[size_t(left[1])], p[size_t(left[2])], eps) > 0)
        out.push_back({left[0], left[1], left[2]});
    if (clockwise)
        for (auto& t : out) std::swap(t[1], t[2]);
    return out;
}

}  // namespace lucerna
