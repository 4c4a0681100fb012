#pragma once
// Settings of the instant radiosity backend.

#include "render/backend/backend.h"
#include "render/vpl/gather_settings.h"
#include "render/vpl/instant_radiosity.h"

namespace lucerna {

struct IrSettings {
    GatherSettings gather;
    int lightPathsPerPass = 32;  // particles per pass: each pass draws a fresh, independent VPL set
    VplOptions vpl;

    // Reads "vpl_paths", "clamp", "compensate", "max_bounces"; throws std::invalid_argument on
    // bad values.
    static IrSettings fromOptions(const RenderSettings& settings);
};

}  // namespace lucerna
