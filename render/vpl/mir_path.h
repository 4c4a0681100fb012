#pragma once
// The light sub-paths the Metropolis instant radiosity chain samples (mir_chain.h), as a function
// of a point u of primary sample space: u drives one light sub-path (the same particle tracer as
// instant radiosity: 5 numbers for the emission, 4 per bounce), whose non-delta vertices
// y_1..y_K are candidate VPLs, each with its importance c_k(u): the light it sends to a fixed set
// of camera points. Choosing k with probability c_k / f, f = sum_k c_k, after a state is accepted
// makes (u, k) distributed in proportion to c_k(u).

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

// The dimension of u for light sub-paths of at most vpl.maxBounces bounces.
int mirPathDimension(const VplOptions& vpl);

// The camera points the chain measures a light path's importance on: `count` camera
// rays stratified over the image (jittered with `seed`), followed through mirrors and glass to
// their first diffuse or glossy vertex x_s; rays that find none are left out.
std::vector<CameraVertex> traceImportancePoints(const RenderScene& scene, const Sensor& camera, int maxSpecularDepth,
                                                int count, uint64_t seed);

// The chain's target: u holds mirPathDimension(vpl) numbers, and the light sub-path's non-delta vertices y_1..y_K are candidate VPLs with
//   c_k(u) = floor + (1 / |S|) sum_s Y(T_s * contribution of y_k at x_s, G clamped),
// the mean image luminance y_k brings to the fixed points S (traceImportancePoints) plus a
// defensive floor > 0 (Hesterberg 1995): every VPL a light path can leave has a density, so the
// estimate converges to the image however poorly S represents it, and no VPL's weight exceeds
// Pc / (n floor). f(u) = sum_k c_k(u) is a deterministic function of u, so a chain stuck on a lucky
// camera point, the way a target measured on one random camera point per state sticks, cannot
// happen.
double evaluateMirLightPath(const RenderScene& scene, const LightSampler& lights, std::span<const CameraVertex> points,
                            const VplOptions& vpl, float maxG, double floor, const std::vector<float>& u,
                            MirPath& path);

// An unbiased estimate of Pc = E[f(u)] for uniformly drawn u from one light sub-path traced with
// `rng`, each vertex measured on `perVertex` members of S drawn at random (with replacement)
// instead of all: |S| / perVertex times fewer shadow rays, for the many samples Pc needs. The path
// plays its own Russian roulette (fewer ends by chance than the chain's), each vertex's floor
// weighted by the chain's probability of reaching it over this path's.
// vertices, if given, receives the path's vertex count (its cost: a ray to each vertex and
// perVertex to S from it).
double estimateMirImportance(const RenderScene& scene, const LightSampler& lights, std::span<const CameraVertex> points,
                             const VplOptions& vpl, float maxG, double floor, int perVertex, Rng& rng,
                             int* vertices = nullptr);

// Vertex k of the path with probability c_k / f, for u in [0, 1); -1 when f is 0.
int choosePathVertex(const MirPath& path, double u);

}  // namespace lucerna
