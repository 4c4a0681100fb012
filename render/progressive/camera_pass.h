#pragma once
// The pass of the backends that trace one camera sample per pixel (path, bdpt): tiles in
// parallel, each pixel's sample drawn from its own scrambled Sobol sequence per half of the film,
// so that the halves stay independent and their difference an honest error estimate (and the
// samples of a pixel stratify its jitter and first bounces). Box filter: the jitter is uniform
// over the pixel's square.

#include "render/backend/film.h"
#include "render/trace/sensor.h"
#include "render/trace/sobol_sampler.h"
#include "render/vpl/tile_scheduler.h"

#include <cstdint>

namespace lucerna {

// Adds one sample to every pixel of the film's half pass % 2 (not finishing the pass).
// makeEstimator(t) runs once per tile t, in the tile's thread, and returns the tile's estimator:
// estimate(x, y, sampler), the radiance of the camera sample at raster point (x, y). A
// non-finite estimate counts as black.
template <class MakeEstimator>
void runCameraPass(const Sensor& camera, int tileSize, uint64_t seed, int pass, Film& film, TaskContext& ctx,
                   const MakeEstimator& makeEstimator) {
    const int half = pass % 2;
    forEachTile(camera.width(), camera.height(), tileSize, ctx, [&](int t, const Tile& pixels) {
        auto estimate = makeEstimator(t);
        for (int y = pixels.y0; y < pixels.y1; ++y)
            for (int x = pixels.x0; x < pixels.x1; ++x) {
                SobolSampler sampler(hashSeed(seed, uint64_t(y) * uint64_t(camera.width()) + uint64_t(x), half),
                                     uint32_t(pass / 2));
                const V2f jitter = sampler.next2D();
                Rgb L = estimate(float(x) + jitter.x, float(y) + jitter.y, sampler);
                if (!isFinite(L)) L = Rgb(0, 0, 0);  // never poison the film
                film.addSample(half, x, y, L);
            }
    });
}

}  // namespace lucerna
