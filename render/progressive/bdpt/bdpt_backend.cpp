#include "render/progressive/bdpt/bdpt_backend.h"

#include "render/backend/backend_options.h"
#include "render/progressive/bdpt/bdpt_tracer.h"
#include "render/progressive/camera_pass.h"
#include "render/progressive/tracing_backend.h"

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
    // One splat list per tile: no contention while the pass runs, a fixed order afterwards.
    std::vector<std::vector<FilmSplat>> splats(size_t(tileCount(camera.width(), camera.height(), settings.tileSize)));
    runCameraPass(camera, settings.tileSize, seed, pass, film, ctx, [&](int t) {
        return [tracer = BdptTracer(scene, settings), &tileSplats = splats[size_t(t)]](
                   float x, float y, SobolSampler& sampler) mutable { return tracer.sample(x, y, sampler, tileSplats); };
    });
    if (ctx.isCancelled()) return;
    const int half = pass % 2;
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

class BdptBackend final : public PassFunctionBackend<BdptSettings> {
public:
    BdptBackend(SceneSnapshot scene, const RenderSettings& settings)
        // Next-event estimation (s = 1) chooses lights as `light_sampler` says (the tree by
        // default); light subpaths start by power (bdpt_tracer.h weighs the two).
        : PassFunctionBackend(std::move(scene), settings, BdptSettings::fromOptions, renderBdptPass) {}

    std::map<std::string, std::string> diagnostics() const override {
        const CameraPower pc = cameraPower(*film_);
        char buf[96];
        std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g", pc.rgb.x, pc.rgb.y, pc.rgb.z);
        return {{"pc", buf}};
    }
};

}  // namespace

std::unique_ptr<Backend> makeBdptBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<BdptBackend>(std::move(scene), settings);
}

}  // namespace lucerna
