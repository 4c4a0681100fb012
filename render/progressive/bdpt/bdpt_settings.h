#pragma once

#include "render/backend/backend.h"

namespace lucerna {

struct BdptSettings {
    // Which strategies contribute. All: every (s, t) with power-heuristic MIS weights. Light
    // tracing: only t = 1 (light subpaths splatted onto the film), each with weight 1; an
    // unbiased but incomplete estimator (it misses paths that reach the camera through a mirror
    // or glass), kept as a check of splatting and camera importance.
    enum class Strategies { All, LightTracing };

    int maxDepth = 1024;           // scattering vertices of a full path (s + t - 2); roulette ends paths long before
    int rouletteStartDepth = 3;    // bounces of a subpath before Russian roulette may end it
    int tileSize = 16;             // pixels on a side per scheduled task
    Strategies strategies = Strategies::All;

    // Reads "max_depth", "rr_depth" and "strategies" (all | light_tracing) from the options;
    // throws std::invalid_argument on bad values.
    static BdptSettings fromOptions(const RenderSettings& settings);
};

}  // namespace lucerna
