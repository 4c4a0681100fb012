#pragma once
// The preview's second VPL source: Metropolis instant radiosity (Segovia, Iehl & Peroche 2007;
// DESIGN.md), the same chain as `--backend mir` (render/vpl/mir_chain.h) run once for a whole
// VPL set: n Metropolis steps over light sub-paths in primary sample space, whose vertices are
// drawn in proportion to the light they send to camera points stratified over the image (plus a
// defensive floor), merged into geometric VPLs, each weighted by its importance-sampling weight.
// The VPLs land where they light what the camera sees, so they depend on the camera and on every
// light: a light edit regenerates the whole set, and a camera move keeps it (the preview answers
// the move at once; regenerate() brings the VPLs up to date).
//
// Differences from the backend, on purpose: the lights are the preview's own (edited) copy, not
// the RenderScene's, so that a light edit needs no new RenderScene; and the camera is the
// preview's current one.

#include "core/scene/scene.h"
#include "render/trace/lights/light_sampler.h"
#include "render/trace/render_scene.h"
#include "render/vpl/mir_chain.h"
#include "render/vpl/vpl.h"

namespace lucerna {

struct MirVplSettings {
    int pathVpls = 256;              // n: chain steps (the geometric VPLs are at most this many)
    float clampFraction = 0.05f;     // as PreviewSettings::clampDistance (0: no clamp)
    // The chain's settings (mir_chain.h), the preview's own values where they differ from its
    // defaults; the preview sets chain.vpl.maxBounces to PreviewSettings::maxBounces.
    MirChainSettings chain = [] {
        MirChainSettings c;
        c.tries = 4;
        c.pcSamples = 1024;
        c.importancePoints = 256;
        return c;
    }();
};

// A VPL set whose powers already carry the normalisation: rendered as is (sum of contributions),
// it estimates the clamped indirect light. Deterministic in seed (single-threaded).
VplSet generateMirVpls(const RenderScene& scene, const LightSampler& lights, const Camera& camera, int width,
                       int height, const MirVplSettings& settings, uint64_t seed);

}  // namespace lucerna
