#pragma once
// VPL generation by light tracing (Keller 1997, "Instant radiosity"): N particles leave the lights
// (LightSampler::sampleEmission, light chosen in proportion to power), are traced with BSDF
// sampling and Russian roulette, and leave a VPL at every non-delta surface they hit. Mirrors and
// glass pass the particle on without a VPL; emitters absorb it.
//
// Power: a VPL carries the particle's throughput divided by N, so that the sum over the set of the
// VPL contributions (vpl.h) is an unbiased estimate of the indirect light at any point.
//
// Per light: the preview regenerates only the VPLs of the light that changed. A "light source"
// here is one emissive object (all its emitting triangles) or one delta light of the scene;
// generateVplsForLight traces particles of that source alone (a light sampler restricted to it),
// so that concatenating the per-source sets, with any number of paths each, is again an unbiased
// VPL set of the whole scene.
//
// Everything is deterministic for a given seed: particle i uses the random stream (seed, i).

#include "render/trace/render_scene.h"
#include "render/trace/sample_generator.h"
#include "render/vpl/vpl.h"

#include <functional>
#include <string>

namespace lucerna {

struct VplOptions {
    int maxBounces = 1024;     // surface interactions a particle may have (its last VPL's `bounce`);
                               // Russian roulette ends particles long before (a low cap is a bias)
    int minBounce = 1;         // VPLs with bounce < minBounce are not kept (the particle goes on);
                               // 2 drops the one-bounce indirect light, keeping longer paths only
    int rouletteStartBounce = 3;  // interactions before Russian roulette may end a particle
};

// One light source of the scene, as the per-light generation numbers them: the emissive objects
// in scene order, then the scene's delta lights (`lights`) in order. Black sources are left out.
struct VplLightSource {
    std::string name;          // the object's or the light's name in the scene file
    bool isObject = false;     // true: an emissive object; false: a delta light
    int sceneIndex = 0;        // index into Scene::objects or Scene::lights
    double power = 0;          // emitted power in LightSampler's units (for sharing paths out)
};

std::vector<VplLightSource> vplLightSources(const RenderScene& scene);

// A VPL set from `lightPaths` particles of all lights (chosen in proportion to power).
VplSet generateVpls(const RenderScene& scene, int lightPaths, uint64_t seed, const VplOptions& options = {});

// A VPL set from `lightPaths` particles of source `sourceIndex` of vplLightSources() alone.
// Empty for an index out of range.
VplSet generateVplsForLight(const RenderScene& scene, int sourceIndex, int lightPaths, uint64_t seed,
                            const VplOptions& options = {});

// The probability that a particle goes on past `bounce`, given its throughput `beta` relative to
// the emitted power (compensated for its survivals so far). Any rule in [0, 1] leaves every
// VPL's expected power as it is; a rule of 0 ends the particle.
using RouletteRule = std::function<double(const Rgb& beta, int bounce)>;

// Instant radiosity's own rule: from options.rouletteStartBounce on, max(beta), at most 0.95, so
// that a particle's throughput stays near 1 and its VPLs near equal power.
double particleSurvival(const Rgb& beta, int bounce, const VplOptions& options);

// One particle: samples an emission from `lights` with the numbers of `u`, traces it and calls
// `deposit` for every VPL (power = throughput * powerScale). Returns the number of VPLs
// deposited. The Metropolis backend drives it with a primary-sample-space stream. `roulette`,
// where given, replaces particleSurvival.
int traceLightPath(const RenderScene& scene, const LightSampler& lights, SampleGenerator& u, float powerScale,
                   const VplOptions& options, const std::function<void(const Vpl&)>& deposit,
                   const RouletteRule& roulette = {});

}  // namespace lucerna
