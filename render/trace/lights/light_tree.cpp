#include "render/trace/lights/light_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lucerna {

namespace {

float angleBetween(const V3f& a, const V3f& b) { return std::acos(std::clamp(a.dot(b), -1.0f, 1.0f)); }

// v rotated by angle about the unit axis k (Rodrigues).
V3f rotate(const V3f& v, const V3f& k, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return v * c + k.cross(v) * s + k * (k.dot(v) * (1 - c));
}

// A tolerance on angles, so that a point on a spot's cone edge is not ruled out by rounding.
constexpr float kAngleTolerance = 1e-4f;

}  // namespace

LightBounds LightBounds::point(const V3f& p, float intensity) {
    LightBounds b;
    b.lo = b.hi = p;
    b.intensity = intensity;
    b.thetaO = kPi;
    b.thetaE = 0;
    return b;
}

LightBounds LightBounds::spot(const V3f& p, const V3f& axis, float coneRad, float intensity) {
    LightBounds b = point(p, intensity);
    b.axis = axis.normalized();
    b.thetaO = std::clamp(coneRad, 0.0f, kPi);
    return b;
}

LightBounds LightBounds::triangle(const V3f& p0, const V3f& p1, const V3f& p2, const V3f& normal, float radianceY) {
    LightBounds b;
    for (int i = 0; i < 3; ++i) {
        b.lo[i] = std::min({p0[i], p1[i], p2[i]});
        b.hi[i] = std::max({p0[i], p1[i], p2[i]});
    }
    b.intensity = radianceY * 0.5f * (p1 - p0).cross(p2 - p0).length();
    b.axis = normal.normalized();
    b.thetaO = 0;
    b.thetaE = kPi / 2;  // the cosine lobe of a one-sided emitter
    return b;
}

LightBounds unite(const LightBounds& a, const LightBounds& b) {
    if (a.intensity <= 0) return b;
    if (b.intensity <= 0) return a;
    LightBounds u;
    for (int i = 0; i < 3; ++i) {
        u.lo[i] = std::min(a.lo[i], b.lo[i]);
        u.hi[i] = std::max(a.hi[i], b.hi[i]);
    }
    // Irradiance adds: the node's bound is the sum of its lights'.
    u.intensity = a.intensity + b.intensity;
    u.thetaE = std::max(a.thetaE, b.thetaE);
    // The smallest cone about both cones (pbrt-v4, DirectionCone Union).
    const float thetaD = angleBetween(a.axis, b.axis);
    if (std::min(thetaD + b.thetaO, kPi) <= a.thetaO) {
        u.axis = a.axis;
        u.thetaO = a.thetaO;
    } else if (std::min(thetaD + a.thetaO, kPi) <= b.thetaO) {
        u.axis = b.axis;
        u.thetaO = b.thetaO;
    } else {
        const float thetaO = 0.5f * (a.thetaO + thetaD + b.thetaO);
        const V3f k = a.axis.cross(b.axis);
        if (thetaO >= kPi || k.length2() < 1e-12f) {
            u.axis = a.axis;
            u.thetaO = kPi;
        } else {
            u.axis = rotate(a.axis, k.normalized(), thetaO - a.thetaO).normalized();
            u.thetaO = thetaO;
        }
    }
    return u;
}

namespace {

// cos(max(0, a - b)) and sin(max(0, a - b)) from the sines and cosines of angles a, b in [0, pi]
// (pbrt-v4's cosSubClamped, sinSubClamped): no inverse trigonometry on the hot path.
float cosSubClamped(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}
float sinSubClamped(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB;
}
float sinFromCos(float c) { return std::sqrt(std::max(0.0f, 1 - c * c)); }

}  // namespace

ImportanceBounds::ImportanceBounds(const LightBounds& b)
    : centre((b.lo + b.hi) * 0.5f), radius2(0.25f * (b.hi - b.lo).length2()), intensity(b.intensity), axis(b.axis),
      cosO(std::cos(b.thetaO)), sinO(std::sin(b.thetaO)), cosE(std::cos(std::min(b.thetaE + kAngleTolerance, kPi))) {}

float importance(const ImportanceBounds& b, const V3f& p, const V3f& n) {
    if (b.intensity <= 0) return 0;
    const V3f toP = p - b.centre;
    const float dist2 = toP.length2();
    // Inside the bounding sphere every direction is possible and the distance no bound: clamp it.
    if (dist2 <= b.radius2) return b.radius2 > 0 ? b.intensity / b.radius2 : 0;
    const float invDist = 1 / std::sqrt(dist2);
    // theta_b: the half-angle of the sphere seen from p.
    const float sinB = std::min(1.0f, std::sqrt(b.radius2) * invDist), cosB = sinFromCos(sinB);
    // theta' = max(0, theta_w - theta_o - theta_b): the smallest angle by which p can lie outside
    // the emission cone; zero importance beyond theta_e.
    float cosP = 1;
    if (b.cosO > -1) {
        const float cosW = b.axis.dot(toP) * invDist, sinW = sinFromCos(cosW);
        const float cosX = cosSubClamped(sinW, cosW, b.sinO, b.cosO), sinX = sinSubClamped(sinW, cosW, b.sinO, b.cosO);
        cosP = cosSubClamped(sinX, cosX, sinB, cosB);
        if (cosP < b.cosE) return 0;
    }
    // The receiving side: a light wholly behind the surface gives nothing (theta_i - theta_b >= 90).
    float cosI = 1;
    if (n.x != 0 || n.y != 0 || n.z != 0) {
        const float cosN = -n.dot(toP) * invDist, sinN = sinFromCos(cosN);
        cosI = cosSubClamped(sinN, cosN, sinB, cosB);
        if (cosI <= 0) return 0;
    }
    return b.intensity * std::max(cosP, 1e-6f) * cosI / dist2;
}

float importance(const LightBounds& b, const V3f& p, const V3f& n) { return importance(ImportanceBounds(b), p, n); }

LightTree::LightTree(const std::vector<LightBounds>& lights) {
    leafOf_.assign(lights.size(), -1);
    std::vector<uint32_t> order;
    for (uint32_t i = 0; i < lights.size(); ++i)
        if (lights[i].intensity > 0 && std::isfinite(lights[i].intensity)) order.push_back(i);
    if (order.empty()) return;
    nodes_.reserve(2 * order.size());
    build(order, 0, order.size(), lights, -1);
}

int32_t LightTree::build(std::vector<uint32_t>& order, size_t begin, size_t end, const std::vector<LightBounds>& lights,
                         int32_t parent) {
    const int32_t index = int32_t(nodes_.size());
    nodes_.push_back({});
    nodes_[index].parent = parent;
    if (end - begin == 1) {
        nodes_[index].bounds = lights[order[begin]];
        nodes_[index].compact = ImportanceBounds(lights[order[begin]]);
        nodes_[index].light = order[begin];
        leafOf_[order[begin]] = index;
        return index;
    }
    // Split at the median of the lights' centres along the longest extent of those centres.
    V3f lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    const auto centre = [&](uint32_t i) { return (lights[i].lo + lights[i].hi) * 0.5f; };
    for (size_t i = begin; i < end; ++i) {
        const V3f c = centre(order[i]);
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], c[k]);
            hi[k] = std::max(hi[k], c[k]);
        }
    }
    const V3f extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const size_t mid = begin + (end - begin) / 2;
    std::nth_element(order.begin() + long(begin), order.begin() + long(mid), order.begin() + long(end),
                     [&](uint32_t a, uint32_t b) { return centre(a)[axis] < centre(b)[axis]; });
    const int32_t left = build(order, begin, mid, lights, index);
    const int32_t right = build(order, mid, end, lights, index);
    nodes_[index].left = left;
    nodes_[index].right = right;
    nodes_[index].bounds = unite(nodes_[left].bounds, nodes_[right].bounds);
    nodes_[index].compact = ImportanceBounds(nodes_[index].bounds);
    return index;
}

float LightTree::weight(int32_t node, const V3f& p, const V3f& n) const {
    return importance(nodes_[node].compact, p, n);
}

float LightTree::leftProbability(const Node& node, const V3f& p, const V3f& n) const {
    float l = weight(node.left, p, n), r = weight(node.right, p, n);
    if (!(l + r > 0)) {
        // Reached through a parent's looser bound, with both children ruled out: chosen by
        // intensity and distance alone, so that every descent ends at a light and the
        // probabilities sum to one (the light chosen then gives nothing, as a failed descent
        // would).
        LightBounds left = nodes_[node.left].bounds, right = nodes_[node.right].bounds;
        left.thetaO = right.thetaO = kPi;
        l = importance(left, p);
        r = importance(right, p);
        if (!(l + r > 0)) l = r = 1;
    }
    return l / (l + r);
}

std::optional<LightTree::Choice> LightTree::sample(const V3f& p, const V3f& n, float u) const {
    // No light reaches p when the root's children all read zero (or a lone light does).
    if (nodes_.empty() || !(weight(0, p, n) > 0)) return std::nullopt;
    int32_t node = 0;
    float pmf = 1;
    while (nodes_[node].left >= 0) {
        const float pLeft = leftProbability(nodes_[node], p, n);
        // One random number for the whole descent: rescaled into the chosen child's share.
        if (u < pLeft) {
            u = std::min(u / pLeft, 0x1.fffffep-1f);
            pmf *= pLeft;
            node = nodes_[node].left;
        } else {
            u = std::min((u - pLeft) / (1 - pLeft), 0x1.fffffep-1f);
            pmf *= 1 - pLeft;
            node = nodes_[node].right;
        }
    }
    if (!(pmf > 0)) return std::nullopt;
    return Choice{nodes_[node].light, pmf, u};
}

float LightTree::pmf(const V3f& p, const V3f& n, uint32_t light) const {
    if (light >= leafOf_.size() || leafOf_[light] < 0 || !(weight(0, p, n) > 0)) return 0;
    float pmf = 1;
    for (int32_t node = leafOf_[light]; nodes_[node].parent >= 0; node = nodes_[node].parent) {
        const Node& parent = nodes_[nodes_[node].parent];
        const float pLeft = leftProbability(parent, p, n);
        pmf *= parent.left == node ? pLeft : 1 - pLeft;
    }
    return pmf;
}

std::vector<uint32_t> LightTree::strongest(const std::function<float(const ImportanceBounds&)>& bound, size_t k) const {
    std::vector<uint32_t> found;
    if (nodes_.empty() || k == 0) return found;
    std::vector<std::pair<float, int32_t>> open;  // a max-heap by bound
    const auto push = [&](int32_t node) {
        const float b = bound(nodes_[size_t(node)].compact);
        if (b > 0) {
            open.emplace_back(b, node);
            std::push_heap(open.begin(), open.end());
        }
    };
    push(0);
    while (!open.empty() && found.size() < k) {
        std::pop_heap(open.begin(), open.end());
        const int32_t node = open.back().second;
        open.pop_back();
        const Node& n = nodes_[size_t(node)];
        if (n.left < 0) {
            found.push_back(n.light);
            continue;
        }
        push(n.left);
        push(n.right);
    }
    return found;
}

}  // namespace lucerna
