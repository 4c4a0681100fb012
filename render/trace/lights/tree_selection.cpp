#include "render/trace/lights/tree_selection.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {

// Emissive triangles share a tree leaf while they are neighbours in the mesh's order with one
// radiance, face within about 25 degrees of the first one and stay within a box four times the
// first one's: a quad lamp is one leaf, a tessellated panel a leaf per patch of up to 16
// triangles. Within a leaf a triangle is chosen by power (its area): they are close enough
// that the tree could not tell them apart, and the descent is shorter.
constexpr size_t kClusterSize = 16;

bool joins(const EmitterTriangle& first, const LightBounds& cluster, const EmitterTriangle& e, float firstDiagonal) {
    if (e.radiance != first.radiance || e.normal.dot(first.normal) < 0.9f) return false;
    LightBounds grown = cluster;
    for (const V3f& p : {e.p0, e.p1, e.p2})
        for (int k = 0; k < 3; ++k) {
            grown.lo[k] = std::min(grown.lo[k], p[k]);
            grown.hi[k] = std::max(grown.hi[k], p[k]);
        }
    return (grown.hi - grown.lo).length() <= 4 * firstDiagonal;
}

}  // namespace

std::optional<LightBounds> deltaLightBounds(const DeltaLight& l, float metersPerUnit) {
    const float intensity = luminance(l.intensity) / (metersPerUnit * metersPerUnit);
    switch (l.type) {
    case LightType::Directional:
    case LightType::Sun: return std::nullopt;
    case LightType::Spot:
        return LightBounds::spot(l.position, l.direction, std::acos(std::clamp(l.cosCone, -1.0f, 1.0f)), intensity);
    case LightType::Luminaire:
        // A spot about the nadir as wide as the table's last lit gamma (an uplight's upper
        // hemisphere included), as strong as the table's peak.
        if (!l.goniometric) return std::nullopt;
        return LightBounds::spot(l.position, l.direction, l.goniometric->emissionConeRad(),
                                 intensity * l.goniometric->peakIntensity());
    default: return LightBounds::point(l.position, intensity);
    }
}

TreeSelection::TreeSelection(const std::vector<EmitterTriangle>& emitters, const std::vector<DeltaLight>& deltas,
                             bool environment, float metersPerUnit, size_t triangleCount)
    : emitterCount_(emitters.size()) {
    std::vector<LightBounds> bounds;
    leafOfTriangle_.assign(triangleCount, -1);
    leafOfLight_.assign(emitters.size() + deltas.size(), -1);
    shareInLeaf_.assign(emitters.size(), 0.0f);
    for (size_t i = 0; i < emitters.size();) {
        const EmitterTriangle& first = emitters[i];
        const float radianceY = luminance(first.radiance);
        LightBounds cluster = LightBounds::triangle(first.p0, first.p1, first.p2, first.normal, radianceY);
        const float firstDiagonal = (cluster.hi - cluster.lo).length();
        size_t end = i + 1;
        while (end < emitters.size() && end - i < kClusterSize && joins(first, cluster, emitters[end], firstDiagonal)) {
            const EmitterTriangle& e = emitters[end];
            cluster = unite(cluster, LightBounds::triangle(e.p0, e.p1, e.p2, e.normal, radianceY));
            ++end;
        }
        double area = 0;
        for (size_t k = i; k < end; ++k) area += emitters[k].area;
        for (size_t k = i; k < end; ++k) {
            shareInLeaf_[k] = float(emitters[k].area / area);
            leafOfTriangle_[emitters[k].triangle] = int32_t(bounds.size());
            leafOfLight_[k] = int32_t(bounds.size());
        }
        leaves_.push_back({uint32_t(i), uint32_t(end), float(area)});
        bounds.push_back(cluster);
        i = end;
    }
    for (size_t i = 0; i < deltas.size(); ++i) {
        const DeltaLight& l = deltas[i];
        const uint32_t index = uint32_t(emitters.size() + i);
        if (l.type == LightType::Directional) {
            directional_.push_back(index);
            continue;
        }
        const std::optional<LightBounds> b = deltaLightBounds(l, metersPerUnit);
        if (!b) continue;
        bounds.push_back(*b);
        leafOfLight_[index] = int32_t(leaves_.size());
        leaves_.push_back({index, index + 1, 0.0f});
    }
    if (environment) directional_.push_back(uint32_t(emitters.size() + deltas.size()));
    if (leaves_.size() == 1 && directional_.empty()) {
        leaves_.clear();
        shareInLeaf_.clear();
        leafOfTriangle_.clear();
        leafOfLight_.clear();
        return;
    }
    tree_ = LightTree(bounds);
}

bool TreeSelection::select(const V3f& p, const V3f& n, float u, size_t& index, float& pdf) const {
    // The tree and the directional lights share the choice evenly.
    const size_t choices = directional_.size() + (tree_.empty() ? 0 : 1);
    if (choices == 0) return false;
    const size_t k = std::min(size_t(u * float(choices)), choices - 1);
    const float share = 1.0f / float(choices);
    if (k < directional_.size()) {
        index = directional_[k];
        pdf = share;
        return true;
    }
    const auto choice = tree_.sample(p, n, std::min(u * float(choices) - float(k), 0x1.fffffep-1f));
    if (!choice) return false;
    const Leaf& leaf = leaves_[choice->light];
    index = leaf.begin;
    // Within a cluster by area, with what is left of u after the descent.
    for (float rest = choice->u; index + 1 < leaf.end && rest >= shareInLeaf_[index]; ++index) rest -= shareInLeaf_[index];
    pdf = share * choice->pmf * (index < emitterCount_ ? shareInLeaf_[index] : 1.0f);
    return pdf > 0;
}

float TreeSelection::areaPdf(uint32_t triangle, const V3f& p, const V3f& n) const {
    const int32_t leaf = leafOfTriangle_[triangle];
    if (leaf < 0) return 0.0f;
    // The triangle's share of its leaf over its area: 1 / the leaf's area.
    const float share = 1.0f / float(directional_.size() + 1);
    return share * tree_.pmf(p, n, uint32_t(leaf)) / leaves_[size_t(leaf)].area;
}

float TreeSelection::pmf(size_t index, const V3f& p, const V3f& n) const {
    const float share = 1.0f / float(directional_.size() + (tree_.empty() ? 0 : 1));
    const int32_t leaf = index < leafOfLight_.size() ? leafOfLight_[index] : -1;
    if (leaf < 0)  // beside the tree (a directional light, the environment), or never chosen
        return std::find(directional_.begin(), directional_.end(), uint32_t(index)) != directional_.end() ? share : 0.0f;
    return share * tree_.pmf(p, n, uint32_t(leaf)) * (index < emitterCount_ ? shareInLeaf_[index] : 1.0f);
}

}  // namespace lucerna
