#include "render/progressive/bdpt/bdpt_backend.h"

#include "render/backend/backend_options.h"
#include "render/progressive/tracing_backend.h"
#include "render/progressive/bdpt/bdpt_tracer.h"
#include "render/trace/sobol_sampler.h"

#include <cstdio>
#include <stdexcept>

namespace lucerna {

BdptSettings BdptSettings::fromOptions(const RenderSettings& settings) {
    BdptSettings s;
    readOption(settings, "max_depth", s.maxDepth, 1);
    readOption(settings, "rr_depth", s.rouletteStartDepth, 1);
    if (const auto it = settings.options.find("strategies"); it != settings.options.end()) {
        if (it->second == "all") s.strategies = BdptSettings::Strategies::All;
        else if (it->second == "light_tracing") s.strategies = BdptSettings::Strategies::LightTracing;
        else throw std::invalid_argument("option strategies must be all or light_tracing, got '" + it->second + "'");
    }
    return s;
}

void renderBdptPass(const RenderScene& scene, const BdptSettings& settings, uint64_t seed, int pass, Film& film,
                    TaskContext& ctx) {
    const Sensor& camera = scene.camera();
    const int tile = settings.tileSize;
    const int tilesX = (camera.width() + tile - 1) / tile, tilesY = (camera.height() + tile - 1) / tile;
    const int half = pass % 2;
    // One splat list per tile: no contention while the pass runs, a fixed order afterwards.
    std::vector<std::vector<FilmSplat>> splats(size_t(tilesX) * tilesY);
    ctx.parallelFor(0, tilesX * tilesY, [&](int t) {
        BdptTracer tracer(scene, settings);
        std::vector<FilmSplat>& tileSplats = splats[size_t(t)];
        const int x0 = (t % tilesX) * tile, y0 = (t / tilesX) * tile;
        const int x1 = std::min(x0 + tile, camera.width()), y1 = std::min(y0 + tile, camera.height());
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                // Each half of the film draws from its own scrambled sequence per pixel (as the
                // path backend does): stratified jitter and first bounces, independent halves.
                SobolSampler sampler(hashSeed(seed, uint64_t(y) * uint64_t(camera.width()) + uint64_t(x), half),
                                     uint32_t(pass / 2));
                const V2f jitter = sampler.next2D();  // box filter: uniform over the pixel's square
                Rgb L = tracer.sample(float(x) + jitter.x, float(y) + jitter.y, sampler, tileSplats);
                if (!isFinite(L)) L = Rgb(0, 0, 0);  // never poison the film
                film.addSample(half, x, y, L);
            }
    });
    if (ctx.isCancelled()) return;
    for (const auto& list : splats) film.addSplats(half, list);
    film.finishPass(half);
}

CameraPower cameraPower(const Film& film) {
    CameraPower pc;
    const Image img = film.image();
    for (const Rgb& p : img.pixels) pc.rgb += Rgbd(p.x, p.y, p.z);
    if (!img.pixels.empty()) pc.rgb /= double(img.pixels.size());
    pc.luminance = luminance(pc.rgb);
    pc.samplesPerPixel = film.samplesPerPixel();
    return pc;
}

CameraPower estimateCameraPower(const RenderScene& scene, const BdptSettings& settings, uint64_t seed, int passes,
                                TaskContext& ctx) {
    Film film(scene.camera().width(), scene.camera().height());
    for (int p = 0; p < passes && !ctx.isCancelled(); ++p) renderBdptPass(scene, settings, seed, p, film, ctx);
    return cameraPower(film);
}

namespace {

class BdptBackend final : public TracingBackend {
public:
    BdptBackend(SceneSnapshot scene, const RenderSettings& settings)
        // By power, always: the bidirectional family's MIS weights and CMLT's path-space
        // values take the recorded pdf of a next-event light vertex as the density it was drawn
        // with, which holds only for a choice that does not depend on the shading point
        // (issue 19: a tree here needs its density at x1 in every strategy's weight).
        : TracingBackend(std::move(scene), settings, LightSelection::Power),
          bdptSettings_(BdptSettings::fromOptions(settings)) {}

    void prepare(TaskContext&) override {
        prepareSceneAndFilm();
    }

    void renderPass(TaskContext& ctx, int pass) override {
        renderBdptPass(*scene_, bdptSettings_, settings_.seed, pass, *film_, ctx);
    }

    std::map<std::string, std::string> diagnostics() const override {
        const CameraPower pc = cameraPower(*film_);
        char buf[96];
        std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g", pc.rgb.x, pc.rgb.y, pc.rgb.z);
        return {{"pc", buf}};
    }

private:
    BdptSettings bdptSettings_;
};

}  // namespace

std::unique_ptr<Backend> makeBdptBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<BdptBackend>(std::move(scene), settings);
}

}  // namespace lucerna
