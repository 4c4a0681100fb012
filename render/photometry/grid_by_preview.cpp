// The preview grid method: hemicubes of preview frames at the grid's points, a fresh VPL set
// each pass, error bars from the pass means (grid_calculation.h).

#include "render/photometry/grid_statistics.h"
#include "render/photometry/sensor_render.h"

#include "render/preview/frame_accumulator.h"
#include "render/preview/headless_backend.h"
#include "render/preview/hemicube_irradiance.h"

#include <chrono>

namespace lucerna {

GridResult computeGridByPreview(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                const GridSettings& settings, TaskContext& ctx,
                                const std::function<void(const GridResult&)>& onPass, GridResult before) {
    GridResult result = std::move(before);
    if (points.empty()) return result;

    const PreparedSensors sensors = prepareSensors(scene, sensorsAt(points, normal));
    RenderSettings options;  // the preview backend's options (vpls, pattern, clamp, ...)
    options.seed = settings.seed;
    options.options = settings.backendOptions;
    PreviewIrradiance preview(scene.snapshot(), previewSettingsFromOptions(options));

    constexpr size_t kPointsPerBlock = 16;  // shared among processes: blocks of points dealt out
    runPointPasses(points.size(), 1, settings, ctx, [&](int pass, std::span<double> passLux) {
        const uint64_t passSeed = hashSeed(settings.seed, uint64_t(pass), 0x9e1d);
        preview.regenerate(passSeed);
        const V2f jitter = uniformJitter(passSeed);  // the faces' pixels, box-filtered over the passes
        for (size_t i = 0; i < points.size() && !ctx.isCancelled(); ++i)
            if (ownsBlock(settings.processes, int(i / kPointsPerBlock)))
                passLux[i] = kLumensPerWatt * double(luminance(preview.irradiance(sensors.lifted[i], jitter.x, jitter.y))) +
                             sensors.deltaLux[i];
    }, onPass, result);
    return result;
}

}  // namespace lucerna
