#include "render/progressive/path/path_backend.h"

#include "render/backend/backend_options.h"
#include "render/progressive/tracing_backend.h"
#include "render/trace/path_tracer.h"
#include "render/trace/sobol_sampler.h"

#include <stdexcept>

namespace lucerna {

PathSettings pathSettingsFromOptions(const RenderSettings& settings) {
    PathSettings s;
    readOption(settings, "max_depth", s.maxDepth, 1);
    readOption(settings, "rr_depth", s.rouletteStartDepth, 1);
    return s;
}

void renderPathPass(const RenderScene& scene, const PathSettings& settings, uint64_t seed, int pass, Film& film,
                    TaskContext& ctx) {
    const Sensor& camera = scene.camera();
    const int tile = settings.tileSize;
    const int tilesX = (camera.width() + tile - 1) / tile, tilesY = (camera.height() + tile - 1) / tile;
    const PathTracer tracer(scene, settings);
    const int half = pass % 2;
    ctx.parallelFor(0, tilesX * tilesY, [&](int t) {
        const int x0 = (t % tilesX) * tile, y0 = (t / tilesX) * tile;
        const int x1 = std::min(x0 + tile, camera.width()), y1 = std::min(y0 + tile, camera.height());
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                // Each half of the film draws from its own scrambled sequence per pixel, so that
                // the halves stay independent and their difference an honest error estimate.
                SobolSampler sampler(hashSeed(seed, uint64_t(y) * uint64_t(camera.width()) + uint64_t(x), half),
                                     uint32_t(pass / 2));
                const V2f jitter = sampler.next2D();  // box filter: uniform over the pixel's square
                Rgb L = tracer.radiance(camera.ray(float(x) + jitter.x, float(y) + jitter.y), sampler);
                if (!isFinite(L)) L = Rgb(0, 0, 0);  // never poison the film
                film.addSample(half, x, y, L);
            }
    });
    if (!ctx.isCancelled()) film.finishPass(half);
}

namespace {

class PathBackend final : public TracingBackend {
public:
    PathBackend(SceneSnapshot scene, const RenderSettings& settings)
        : TracingBackend(std::move(scene), settings), pathSettings_(pathSettingsFromOptions(settings)) {}

    void prepare(TaskContext&) override {
        prepareSceneAndFilm();
    }

    void renderPass(TaskContext& ctx, int pass) override {
        renderPathPass(*scene_, pathSettings_, settings_.seed, pass, *film_, ctx);
    }

private:
    PathSettings pathSettings_;
};

}  // namespace

std::unique_ptr<Backend> makePathBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<PathBackend>(std::move(scene), settings);
}

}  // namespace lucerna
