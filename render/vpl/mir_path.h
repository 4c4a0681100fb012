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

#include <span>
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

// The camera points the backend's chain measures a light path's importance on: `count` camera
// rays stratified over the image (jittered with `seed`), followed through mirrors and glass to
// their first diffuse or glossy vertex x_s; rays that find none are left out.
std::vector<CameraVertex> traceImportancePoints(const RenderScene& scene, const Sensor& camera, int maxSpecularDepth,
                                                int count, uint64_t seed);

// The backend's target, over a light sub-path alone: u holds layout.lightDimensions numbers, and
// the sub-path's non-delta vertices y_1..y_K are candidate VPLs with
//   c_k(u) = floor + (1 / |S|) sum_s Y(T_s * contribution of y_k at x_s, G clamped),
// the mean image luminance y_k brings to the fixed points S (traceImportancePoints) plus a
// defensive floor > 0 (Hesterberg 1995): every VPL a light path can leave has a density, so the
// estimator is unbiased however poorly S represents the image, and no VPL's weight exceeds
// Pc / (n floor). f(u) = sum_k c_k(u) is a deterministic function of u, so a chain stuck on a lucky
// camera point, the way a target measured on one random camera point per state sticks, cannot
// happen.
double evaluateMirLightPath(const RenderScene& scene, const LightSampler& lights, std::span<const CameraVertex> points,
                            const VplOptions& vpl, float maxG, double floor, const MirPathLayout& layout,
                            const std::vector<float>& u, MirPath& path);

// Vertex k of the path with probability c_k / f, for u in [0, 1); -1 when f is 0.
int choosePathVertex(const MirPath& path, double u);

}  // namespace lucerna
