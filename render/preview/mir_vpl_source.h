#pragma once
// The preview's second VPL source: Metropolis instant radiosity (Segovia, Iehl & Peroche 2007;
// DESIGN.md), the same chain as `--backend mir` (render/progressive/mir/: metropolis.h,
// mir_path.h) run once for a whole VPL set:
//   1. n multiple-try Metropolis steps over camera-to-light paths in primary sample space, one
//      path VPL per step, consecutive equal path VPLs merged into one geometric VPL of count k_i;
//   2. Pc, the mean image luminance of the clamped VPL term, from the chain's uniform samples;
//   3. each geometric VPL scaled so that its image contribution (measured on the CPU with Embree,
//      one camera sample per block of pixels, visibility included) equals k_i Pc / n.
// The VPLs land where they light what the camera sees, so they depend on the camera and on every
// light: a light edit regenerates the whole set, and a camera move keeps it (the preview answers
// the move at once; regenerate() brings the VPLs up to date).
//
// Differences from the backend, on purpose: the lights are the preview's own (edited) copy, not
// the RenderScene's, so that a light edit needs no new RenderScene; and the camera is the
// preview's current one.

#include "core/scene.h"
#include "render/trace/light_sampler.h"
#include "render/trace/render_scene.h"
#include "render/vpl/vpl.h"

namespace lucerna {

struct MirVplSettings {
    int pathVpls = 256;              // n: chain steps (the geometric VPLs are at most this many)
    int tries = 4;                   // multiple-try trials per step
    float largeStepProbability = 0.3f;
    int startCandidates = 1024;
    int pcSamples = 1024;            // extra uniform samples refining Pc
    int normalizationSamples = 4096; // camera samples measuring each VPL's image contribution
    float clampFraction = 0.05f;     // as PreviewSettings::clampDistance (0: no clamp)
    int maxBounces = 8;
};

// A VPL set whose powers already carry the normalisation: rendered as is (sum of contributions),
// it estimates the clamped indirect light. Deterministic in seed (single-threaded).
VplSet generateMirVpls(const RenderScene& scene, const LightSampler& lights, const Camera& camera, int width,
                       int height, const MirVplSettings& settings, uint64_t seed);

}  // namespace lucerna
