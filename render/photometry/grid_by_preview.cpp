// The preview grid method: hemicubes of preview frames at the grid's points, a fresh VPL set
// each pass, error bars from the pass means (grid_calculation.h).

#include "render/photometry/grid_statistics.h"
#include "render/photometry/sensor_render.h"

#include "render/preview/frame_accumulator.h"
#include "render/preview/headless_backend.h"
#include "render/preview/hemicube_irradiance.h"

#include <chrono>
#include <optional>

namespace lucerna {

GridResult computeGridByPreview(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                const GridSettings& settings, TaskContext& ctx,
                                const std::function<void(const GridResult&)>& onPass, GridResult before) {
    GridResult result = std::move(before);
    if (points.empty()) return result;

    const PreparedSensors sensors = prepareSensors(scene, sensorsAt(points, normal));
    // The cylinder: four vertical sensors a point turned by a random azimuth each pass, their mean
    // plus the delta lights' exact cylindrical part (grid_statistics.h).
    const bool cylindrical = settings.quantity == GridQuantity::Cylindrical;
    const std::vector<double> cylinderDeltaLux =
        cylindrical ? cylindricalDeltaLux(scene, points, normal, /*throughPanes=*/false) : std::vector<double>{};
    std::optional<IrradianceEstimator> lifter;  // moves the turned sensors off surfaces
    if (cylindrical) lifter.emplace(scene);
    RenderSettings options;  // the preview backend's options (vpls, pattern, clamp, ...)
    options.seed = settings.seed;
    options.options = settings.backendOptions;
    PreviewIrradiance preview(scene.snapshot(), previewSettingsFromOptions(options));

    constexpr size_t kPointsPerBlock = 16;  // shared among processes: blocks of points dealt out
    runPointPasses(points.size(), 1, settings, ctx, [&](int pass, std::span<double> passLux) {
        const uint64_t passSeed = hashSeed(settings.seed, uint64_t(pass), 0x9e1d);
        preview.regenerate(passSeed);
        const V2f jitter = uniformJitter(passSeed);  // the faces' pixels, box-filtered over the passes
        const std::vector<IrradianceSensor> vertical =
            cylindrical ? cylinderSensorsAt(points, normal, 0.5f * kPi * Rng(passSeed, 0x617a).next1D())
                        : std::vector<IrradianceSensor>{};
        for (size_t i = 0; i < points.size() && !ctx.isCancelled(); ++i) {
            if (!ownsBlock(settings.processes, int(i / kPointsPerBlock))) continue;
            if (!cylindrical) {
                passLux[i] = kLumensPerWatt * double(luminance(preview.irradiance(sensors.lifted[i], jitter.x, jitter.y))) +
                             sensors.deltaLux[i];
                continue;
            }
            double sum = 0;
            for (size_t k = 0; k < 4; ++k)
                sum += double(luminance(preview.irradiance(lifter->lifted(vertical[4 * i + k]), jitter.x, jitter.y)));
            passLux[i] = kLumensPerWatt * sum / 4 + cylinderDeltaLux[i];
        }
    }, onPass, result);
    return result;
}

}  // namespace lucerna
