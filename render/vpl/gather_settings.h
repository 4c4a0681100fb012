#pragma once
// Settings of VPL gathering (vpl_gatherer.h), shared by instant radiosity, Metropolis instant
// radiosity and the calculation grids.

#include "render/backend/backend.h"

namespace lucerna {

struct GatherSettings {
    // Clamp distance of the geometric term, as a fraction of the scene's bounding radius
    // (vpl_contribution.h). 0: no clamp (and nothing to compensate).
    float clampFraction = 0.1f;
    // Estimate the clamped-away residual with short path-traced paths (Kollig & Keller 2004), so
    // that the estimate is consistent. Off: biased (darker near corners), for measurements only.
    bool compensate = true;
    // Samples of the direct light per camera sample (next-event estimation and a BSDF sample
    // each); the residual takes the first one's BSDF sample.
    int directSamples = 1;
    int maxSpecularDepth = 16;  // camera bounces through mirrors and glass before giving up
    int tileSize = 16;
};

// Reads "clamp", "compensate" and "direct_samples" over `defaults`.
GatherSettings gatherSettingsFromOptions(const RenderSettings& settings, GatherSettings defaults = {});

}  // namespace lucerna
