#pragma once
// Settings of the path tracer (render/trace/path_tracer.h), shared by the path backend, the
// residual paths of VPL gathering and the irradiance estimator of calculation grids.

namespace lucerna {

struct PathSettings {
    int maxDepth = 1024;           // bounces; Russian roulette ends paths long before
    int rouletteStartDepth = 3;    // bounces before Russian roulette may end a path
    int tileSize = 16;             // pixels on a side per scheduled task
};

}  // namespace lucerna
