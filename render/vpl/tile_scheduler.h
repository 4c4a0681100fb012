#pragma once
// Tiles of the image in parallel, each pixel visited once by one thread: the scheduling of the
// VPL-gathering passes. fn(x, y) must only write pixel (x, y)'s own state.

#include "core/task_system.h"

#include <algorithm>

namespace lucerna {

template <class Fn>
void forEachPixel(int width, int height, int tile, TaskContext& ctx, const Fn& fn) {
    const int tilesX = (width + tile - 1) / tile, tilesY = (height + tile - 1) / tile;
    ctx.parallelFor(0, tilesX * tilesY, [&](int t) {
        const int x0 = (t % tilesX) * tile, y0 = (t / tilesX) * tile;
        const int x1 = std::min(x0 + tile, width), y1 = std::min(y0 + tile, height);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) fn(x, y);
    });
}

}  // namespace lucerna
