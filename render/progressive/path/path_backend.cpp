#include "render/progressive/path/path_backend.h"

#include "render/backend/backend_options.h"
#include "render/progressive/camera_pass.h"
#include "render/progressive/tracing_backend.h"
#include "render/trace/path_tracer.h"

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
    const PathTracer tracer(scene, settings);
    runCameraPass(camera, settings.tileSize, seed, pass, film, ctx, [&](int) {
        return [&](float x, float y, SobolSampler& sampler) { return tracer.radiance(camera.ray(x, y), sampler); };
    });
    if (!ctx.isCancelled()) film.finishPass(pass % 2);
}

std::unique_ptr<Backend> makePathBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<PassFunctionBackend<PathSettings>>(std::move(scene), settings, pathSettingsFromOptions,
                                                               renderPathPass);
}

}  // namespace lucerna
