#pragma once
// A light BVH for choosing among many lights by their importance at a shading point (Conty
// Estevez and Kulla, "Importance Sampling of Many Lights with Adaptive Tree Splitting", HPG 2018;
// pbrt-v4's BVHLightSampler). Each node bounds its lights' positions (a box), their intensity
// and the directions they emit in (an orientation cone); a point descends from the root with one
// random number, each child chosen in proportion to its importance there. The probability of
// any light at any point is computable (pmf), because MIS needs it.
//
// The bounds are conservative: a node's importance at a point is zero only where none of its
// lights can send light, so the tree never turns light into bias. TreeSelection
// (tree_selection.h) uses it for next-event estimation with LightSelection::Tree.

#include "core/math.h"

#include <functional>
#include <optional>
#include <vector>

namespace lucerna {

// What a light (or a node, the union of its lights) can do: where it is, how strong it is at
// most, in which directions it emits. Directions as in pbrt-v4: every emission direction lies
// within thetaO of axis, and the light leaves a surface at most thetaE beyond that (pi/2 for a
// one-sided emitter's cosine lobe, 0 for a spot whose cone is thetaO).
struct LightBounds {
    V3f lo{0, 0, 0}, hi{0, 0, 0};  // the positions' box, scene units
    float intensity = 0;  // an upper bound of the luminance of its intensity in any direction, W/sr
                          // (an emitter: Y(radiance) x area, its intensity along the normal)
    V3f axis{0, 0, 1};    // unit
    float thetaO = kPi;   // radians, in [0, pi]
    float thetaE = 0;     // radians, in [0, pi/2]

    static LightBounds point(const V3f& p, float intensity);
    static LightBounds spot(const V3f& p, const V3f& axis, float coneRad, float intensity);
    static LightBounds triangle(const V3f& p0, const V3f& p1, const V3f& p2, const V3f& normal, float radianceY);
};

// The bounds of two lights together.
LightBounds unite(const LightBounds& a, const LightBounds& b);

// What importance() reads of a LightBounds, precomputed for each node of a tree: the box's
// bounding sphere, and the cosines of the cone angles (thetaE with a small tolerance, so that a
// point on a spot's cone edge is not ruled out by rounding).
struct ImportanceBounds {
    ImportanceBounds() = default;
    explicit ImportanceBounds(const LightBounds& b);
    V3f centre{0, 0, 0};
    float radius2 = 0;  // squared radius of the box's bounding sphere
    float intensity = 0;
    V3f axis{0, 0, 1};
    float cosO = -1, sinO = 0, cosE = 1;
};

// An upper bound of the irradiance the lights can give at p, up to a common factor: intensity x
// cos of the smallest angle by which p can lie outside the emission cone x cos of the smallest
// angle between n and a direction to the lights / squared distance, the distance no smaller than
// the radius of the box's bounding sphere. n is the unit normal of the side p receives light on
// (an opaque surface's side facing the viewer), or zero where light from any side counts.
// 0 only where none of the lights can reach that side of p.
float importance(const LightBounds& b, const V3f& p, const V3f& n = V3f(0, 0, 0));
float importance(const ImportanceBounds& b, const V3f& p, const V3f& n);

class LightTree {
public:
    LightTree() = default;
    // The tree over `lights` (their indices are kept); lights of zero intensity are left out and
    // have probability 0.
    explicit LightTree(const std::vector<LightBounds>& lights);

    bool empty() const { return nodes_.empty(); }

    struct Choice {
        uint32_t light = 0;
        float pmf = 0;
        float u = 0;  // what is left of u after the descent: uniform in [0, 1) again
    };
    // A light for the point p (receiving on the side of the unit normal n, or any side for n
    // zero; importance()) by the random number u in [0, 1); nothing where the bounds say that no
    // light can reach p. Otherwise the probabilities of all lights sum to one; a light that
    // cannot reach p may still be chosen where the bounds are loose, never the other way.
    std::optional<Choice> sample(const V3f& p, const V3f& n, float u) const;
    std::optional<Choice> sample(const V3f& p, float u) const { return sample(p, V3f(0, 0, 0), u); }
    // The probability that sample(p, n, u) chooses `light` for a uniform u.
    float pmf(const V3f& p, const V3f& n, uint32_t light) const;
    float pmf(const V3f& p, uint32_t light) const { return pmf(p, V3f(0, 0, 0), light); }

    // Up to k lights of the largest positive bound(leaf), strongest first, by a best-first descent
    // that opens the node of the largest bound(node) next: O(k log n) bounds where a node's bound
    // is at least its lights' (as with importance-like bounds, the node's intensity being their
    // sum), the exact k largest then. The preview's choice of lights per block of the image.
    std::vector<uint32_t> strongest(const std::function<float(const ImportanceBounds&)>& bound, size_t k) const;

private:
    struct Node {
        LightBounds bounds;
        ImportanceBounds compact;
        int32_t left = -1, right = -1;  // children; -1 for a leaf
        int32_t parent = -1;
        uint32_t light = 0;  // leaf: which light
    };
    int32_t build(std::vector<uint32_t>& order, size_t begin, size_t end, const std::vector<LightBounds>& lights,
                  int32_t parent);
    float weight(int32_t node, const V3f& p, const V3f& n) const;
    // The probability of choosing the left child of `node` at p.
    float leftProbability(const Node& node, const V3f& p, const V3f& n) const;

    std::vector<Node> nodes_;     // nodes_[0] is the root
    std::vector<int32_t> leafOf_; // by light: its leaf node, -1 when left out
};

}  // namespace lucerna
