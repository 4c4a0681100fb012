#pragma once
// Settings of the instant radiosity backend.

#include "render/backend/backend.h"
#include "render/vpl/gather_settings.h"
#include "render/vpl/instant_radiosity.h"

namespace lucerna {

struct IrSettings {
    GatherSettings gather;
    int lightPathsPerPass = 32;  // particles per VPL set: each pass draws fresh, independent sets
    // Interleaved sampling (Keller & Heidrich 2001): each pass draws interleave^2 independent VPL
    // sets and each pixel gathers one of them, drawn at random. A
    // pixel's estimate is as noisy as with one set, but the error shared by all pixels (a set's
    // total power, which in a closed bright room varies with the particles' random path lengths)
    // falls by interleave^2 at almost no cost: particles are cheap next to the gather. Fewer
    // where the film has under 64 pixels a set.
    int interleave = 8;
    VplOptions vpl;

    // Reads "vpl_paths", "interleave", "clamp", "compensate", "residual_vpls" (0), "direct_samples"
    // (1), "max_bounces"; throws std::invalid_argument on bad values.
    static IrSettings fromOptions(const RenderSettings& settings);
};

}  // namespace lucerna
