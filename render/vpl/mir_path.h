#pragma once
// The paths the MIR chain samples, as a function of a point u of primary sample space.
//
// u = (camera part | light part). The camera part picks a raster point (2 numbers, uniform over
// the image) and follows the camera ray through mirrors and glass to its first diffuse/glossy
// vertex x1 (3 numbers per specular bounce). The light part traces one light sub-path (the same
// particle tracer as instant radiosity: 5 numbers for the emission, 4 per bounce) whose
// non-delta vertices y_1..y_K are candidate VPLs. The two parts read separate ranges of u, so a
// small step perturbs each path locally.
//
// The complete path through VPL k, camera -> x1 -> y_k -> ... -> light, contributes
//   c_k(u) = Y(T_cam * contribution of VPL y_k at x1, G clamped),
// Y the luminance; the chain's target is f(u) = sum_k c_k(u). Its integral over u is Pc, the mean
// over the image of the luminance of the clamped VPL term (what the VPLs must bring to the camera).
// Choosing k with probability c_k / f after a state is accepted makes (u, k) distributed in
// proportion to c_k(u): a complete path sampled in proportion to its image contribution, whose
// light-side half (y_k and the sub-path behind it) is the path VPL.

#include "render/vpl/vpl_gatherer.h"

#include <vector>

namespace lucerna {

struct MirPath {
    std::vector<Vpl> vpls;             // y_1..y_K (power: the sub-path's throughput, unnormalised)
    std::vector<double> contribution;  // c_k(u)
};

// Light bounces whose random numbers are part of the chain's state (and mutated by small steps);
// later bounces, rare after Russian roulette, draw from padding (mir_path.cpp).
inline constexpr int kStoredLightBounces = 12;

struct MirPathLayout {
    int cameraDimensions = 0, lightDimensions = 0;
    int dimension() const { return cameraDimensions + lightDimensions; }
};

MirPathLayout mirPathLayout(const GatherSettings& gather, const VplOptions& vpl);

// f(u) = sum_k c_k(u); fills `path`. maxG: the gatherers' clamp bound. The light sub-path
// starts on `lights` and the camera ray leaves `camera` (the scene's own, or the interactive
// preview's current ones).
double evaluateMirPath(const RenderScene& scene, const LightSampler& lights, const Sensor& camera,
                       const GatherSettings& gather, const VplOptions& vpl, float maxG, const MirPathLayout& layout,
                       const std::vector<float>& u, MirPath& path);

// Vertex k of the path with probability c_k / f, for u in [0, 1); -1 when f is 0.
int choosePathVertex(const MirPath& path, double u);

}  // namespace lucerna
