#pragma once
// Settings of the instant radiosity backend (and of the gathering that the Metropolis instant
// radiosity backend shares with it).

#include "render/progressive/backend.h"
#include "render/vpl/instant_radiosity.h"

namespace lucerna {

struct GatherSettings {
    // Clamp distance of the geometric term, as a fraction of the scene's bounding radius
    // (vpl_contribution.h). 0: no clamp (and nothing to compensate).
    float clampFraction = 0.1f;
    // Estimate the clamped-away residual with short path-traced paths (Kollig & Keller 2004), so
    // that the estimate is consistent. Off: biased (darker near corners), for measurements only.
    bool compensate = true;
    int maxSpecularDepth = 16;  // camera bounces through mirrors and glass before giving up
    int tileSize = 16;
};

struct IrSettings {
    GatherSettings gather;
    int lightPathsPerPass = 32;  // particles per pass: each pass draws a fresh, independent VPL set
    VplOptions vpl;

    // Reads "vpl_paths", "clamp", "compensate", "max_bounces"; throws std::invalid_argument on
    // bad values.
    static IrSettings fromOptions(const RenderSettings& settings);
};

// Reads "clamp" and "compensate".
GatherSettings gatherSettingsFromOptions(const RenderSettings& settings);

}  // namespace lucerna
