#pragma once
// Next-event estimation's choice of a light by a light tree (LightSelection::Tree): emissive
// triangles in clusters of neighbours (a quad lamp one leaf, a tessellated panel a leaf per
// patch), each point, spot and luminaire light a leaf of its own, and the directional lights and
// the environment beside the tree, each chosen as often as the whole tree (as in pbrt-v4).
// Lights are numbered as LightSample::light: the emissive triangles, the delta lights, then the
// environment.

#include "render/trace/lights/delta_light.h"
#include "render/trace/lights/emitter_triangle.h"
#include "render/trace/lights/light_tree.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace lucerna {

// A point, spot or luminaire light's bounds for the tree (luminance of its peak intensity in
// W/sr per scene unit squared); nothing for directional lights and the sun, which no box bounds,
// and for a luminaire without its table.
std::optional<LightBounds> deltaLightBounds(const DeltaLight& light, float metersPerUnit);

class TreeSelection {
public:
    TreeSelection() = default;
    // `environment`: whether the scene has one. triangleCount sizes the per-triangle tables.
    // Empty where one cluster or one light and nothing beside it would make the tree choose as
    // power selection does, only slower.
    TreeSelection(const std::vector<EmitterTriangle>& emitters, const std::vector<DeltaLight>& deltas,
                  bool environment, float metersPerUnit, size_t triangleCount);

    bool empty() const { return leaves_.empty() && directional_.empty(); }
    // Whether the tree holds emissive triangles (areaPdf() is theirs then).
    bool hasEmitters() const { return !leaves_.empty(); }

    // A light for the point p receiving on the side of the unit normal n (zero: any side; see
    // LightTree::sample) by u in [0, 1), and the probability of choosing it there; false where
    // no light can reach p. A triangle of a cluster is chosen by area.
    bool select(const V3f& p, const V3f& n, float u, size_t& index, float& pdf) const;
    // The probability of choosing a given directional light or the environment, the same at
    // every point.
    float besidePdf() const { return 1.0f / float(directional_.size() + (tree_.empty() ? 0 : 1)); }
    // With hasEmitters(): the density per unit area with which select() at p (receiving side
    // n) and a uniform point of the chosen triangle give a point of emissive render-scene
    // triangle `triangle`.
    float areaPdf(uint32_t triangle, const V3f& p, const V3f& n) const;
    // The probability that select() at p (receiving side n) chooses light `index`
    // (LightSample::light numbering): what select() returns as its pdf when it chooses it.
    float pmf(size_t index, const V3f& p, const V3f& n) const;

private:
    // The tree's light k is leaves_[k]: a cluster of emissive triangles or one delta light.
    struct Leaf {
        uint32_t begin = 0, end = 0;  // lights [begin, end)
        float area = 0;               // a cluster's area, scene units^2
    };
    size_t emitterCount_ = 0;
    LightTree tree_;
    std::vector<Leaf> leaves_;
    std::vector<uint32_t> directional_;  // the lights beside the tree
    std::vector<float> shareInLeaf_;     // by emitter: its share of its cluster (by area)
    std::vector<int32_t> leafOfTriangle_;  // by render-scene triangle: its leaf (-1: none)
    std::vector<int32_t> leafOfLight_;     // by light: its leaf (-1: beside the tree, or never chosen)
};

}  // namespace lucerna
