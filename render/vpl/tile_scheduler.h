#pragma once
// Tiles of the image in parallel, each pixel visited once by one thread: the scheduling of the
// camera passes (path, bdpt) and the VPL-gathering passes (ir, mir).

#include "core/task_system.h"

#include <algorithm>

namespace lucerna {

// The pixels [x0, x1) x [y0, y1) of one tile.
struct Tile {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

inline int tileCount(int width, int height, int tile) {
    return ((width + tile - 1) / tile) * ((height + tile - 1) / tile);
}

// fn(t, pixels) for each tile t in [0, tileCount()), rows of tiles from the top; fn must only
// write its tile's own state.
template <class Fn>
void forEachTile(int width, int height, int tile, TaskContext& ctx, const Fn& fn) {
    const int tilesX = (width + tile - 1) / tile, tilesY = (height + tile - 1) / tile;
    ctx.parallelFor(0, tilesX * tilesY, [&](int t) {
        const int x0 = (t % tilesX) * tile, y0 = (t / tilesX) * tile;
        fn(t, Tile{x0, y0, std::min(x0 + tile, width), std::min(y0 + tile, height)});
    });
}

// fn(x, y) for each pixel; fn must only write pixel (x, y)'s own state.
template <class Fn>
void forEachPixel(int width, int height, int tile, TaskContext& ctx, const Fn& fn) {
    forEachTile(width, height, tile, ctx, [&](int, const Tile& pixels) {
        for (int y = pixels.y0; y < pixels.y1; ++y)
            for (int x = pixels.x0; x < pixels.x1; ++x) fn(x, y);
    });
}

}  // namespace lucerna
