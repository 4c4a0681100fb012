#pragma once

#include "render/progressive/backend.h"

namespace lucerna {

struct PathSettings {
    int maxDepth = 1024;           // bounces; Russian roulette ends paths long before
    int rouletteStartDepth = 3;    // bounces before Russian roulette may end a path
    int tileSize = 16;             // pixels on a side per scheduled task

    // Reads "max_depth", "rr_depth" from the options; throws std::invalid_argument on bad values.
    static PathSettings fromOptions(const RenderSettings& settings);
};

}  // namespace lucerna
