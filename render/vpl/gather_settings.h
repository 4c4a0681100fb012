#pragma once
// Settings of VPL gathering (vpl_gatherer.h), shared by instant radiosity, Metropolis instant
// radiosity and the calculation grids.

#include "render/backend/backend.h"

namespace lucerna {

struct GatherSettings {
    // Clamp distance of the geometric term, as a fraction of the scene's bounding radius
    // (vpl_contribution.h). 0: no clamp (and nothing to compensate).
    float clampFraction = 0.1f;
    // Estimate the clamped-away residual (Kollig & Keller 2004), so that the estimate is
    // consistent. Off: biased (darker near corners), for measurements only.
    bool compensate = true;
    // The share of the residual estimated at x2 by the gather's own terms (x2's direct light, the
    // VPLs, x2's own residual by a path) rather than by a path traced from x2 (Kollig & Keller):
    // both estimate the light leaving x2 toward x1, so any share in [0, 1] is unbiased, and
    // between 0 and 1 both are drawn and weighed by it. A path finds x2's indirect light as path
    // tracing does, the noise the VPLs are there to avoid (mir on the daylit office); VPLs near
    // x2 are correlated with x1's, and with the chain's (mir on room (e), the Cornell box).
    // mir takes half where the scene has daylight (mir_settings.h); ir, whose VPL sets per
    // pixel are small, 0 (1.03 and 1.24 of 0's relmse with 1 and with a half on the daylit
    // office).
    float residualVplShare = 0.0f;
    // Samples of the direct light per camera sample (next-event estimation and a BSDF sample
    // each); the residual takes the first one's BSDF sample.
    int directSamples = 1;
    int maxSpecularDepth = 16;  // camera bounces through mirrors and glass before giving up
    int tileSize = 16;
};

// Reads "clamp", "compensate", "residual_vpls" (the share above) and "direct_samples" over
// `defaults`.
GatherSettings gatherSettingsFromOptions(const RenderSettings& settings, GatherSettings defaults = {});

}  // namespace lucerna
