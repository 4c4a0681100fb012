#include "render/photometry/grid_calculation.h"

#include "render/photometry/grid_auto.h"
#include "render/photometry/grid_diagnosis.h"
#include "render/photometry/grid_statistics.h"
#include "render/vpl/instant_radiosity.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace lucerna {

std::optional<GridMethod> gridMethodFromName(const std::string& name) {
    for (GridMethod m : kGridMethods)
        if (name == gridMethodName(m)) return m;
    return std::nullopt;
}

const char* gridMethodName(GridMethod method) {
    switch (method) {
    case GridMethod::Path: return "path";
    case GridMethod::Vpl: return "ir";
    case GridMethod::Bdpt: return "bdpt";
    case GridMethod::Mir: return "mir";
    case GridMethod::Mlt: return "mlt";
    case GridMethod::Cmlt: return "cmlt";
    case GridMethod::Preview: return "preview";
    }
    return "?";
}

namespace {
// The path and ir methods: their irradiance estimators, pass by pass.
GridResult computeGridByEstimator(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                  const GridSettings& settings, TaskContext& ctx,
                                  const std::function<void(const GridResult&)>& onPass, GridResult result) {
    const IrradianceEstimator estimator(scene);
    const std::vector<IrradianceSensor> sensors = sensorsAt(points, normal);
    const bool cylindrical = settings.quantity == GridQuantity::Cylindrical;
    const Frame axisFrame(toFloat(normal).normalized());
    const int count = int(points.size());
    const int pointsPerTask = 16;
    const int samples =
        settings.samplesPerPass > 0 ? settings.samplesPerPass : settings.method == GridMethod::Path ? 16 : 1;
    const int tasks = (count + pointsPerTask - 1) / pointsPerTask;
    // The delta lights' direct part is exact and the same every sample: once per point. For the
    // cylinder it is added to the pass means, the vertical planes' samples leaving it out.
    std::vector<Rgb> deltaE(points.size(), Rgb(0, 0, 0));
    std::vector<double> cylinderDeltaLux(points.size(), 0.0);
    ctx.parallelFor(0, tasks, [&](int task) {
        for (int i = task * pointsPerTask; i < std::min(count, (task + 1) * pointsPerTask); ++i) {
            if (cylindrical)
                cylinderDeltaLux[size_t(i)] = kLumensPerWatt * double(luminance(estimator.deltaLightsCylindrical(
                                                                   sensors[size_t(i)].position, axisFrame.n)));
            else
                deltaE[size_t(i)] = estimator.deltaLightsIrradiance(sensors[size_t(i)]);
        }
    });

    runPointPasses(points.size(), samples, settings, ctx, [&](int pass, std::span<double> passMean) {
        VplSet vpls;
        if (settings.method == GridMethod::Vpl)
            vpls = generateVpls(scene, settings.vplPathsPerPass, hashSeed(settings.seed, uint64_t(pass), 0x9d1));
        ctx.parallelFor(0, tasks, [&](int task) {
            if (!ownsBlock(settings.processes, task)) return;  // another process's points
            for (int i = task * pointsPerTask; i < std::min(count, (task + 1) * pointsPerTask); ++i) {
                IrradianceSensor sensor = sensors[size_t(i)];
                Rng rng(hashSeed(settings.seed, uint64_t(pass)), uint64_t(i));
                // The cylinder: a vertical plane per sample, azimuths stratified over the circle.
                const float azimuthOffset = cylindrical ? rng.next1D() : 0.0f;
                double sum = 0;
                for (int s = 0; s < samples; ++s) {
                    if (cylindrical)
                        sensor.normal = azimuthDirection(axisFrame, 2.0f * kPi * (float(s) + azimuthOffset) / float(samples));
                    const Rgb* exact = &deltaE[size_t(i)];
                    const Rgb E = settings.method == GridMethod::Path ? estimator.samplePath(sensor, rng, exact)
                                                                      : estimator.sampleVpl(sensor, rng, vpls, exact);
                    if (isFinite(E)) sum += kLumensPerWatt * double(luminance(E));
                }
                passMean[size_t(i)] = sum / samples + cylinderDeltaLux[size_t(i)];
            }
        });
    }, onPass, result);
    return result;
}
}  // namespace

GridResult computeGridIlluminance(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                  const GridSettings& requested, TaskContext& ctx,
                                  const std::function<void(const GridResult&)>& onPass) {
    GridResult start = emptyGridResult(points.size(), pointsInsideGeometry(scene, points, normal));
    const std::vector<uint8_t> throughGlass = pointsLitThroughGlass(scene, points, normal);
    for (size_t i = 0; i < points.size(); ++i) start.litThroughGlass += throughGlass[i] && !start.insideGeometry[i];
    GridSettings settings = requested;
    if (settings.autoMethod && !settings.processes)
        return computeGridByAuto(scene, points, normal, settings, ctx, onPass, std::move(start));
    if (settings.autoMethod) settings.method = start.litThroughGlass > 0 ? GridMethod::Bdpt : GridMethod::Path;
    start.method = settings.method;
    start.errorBarUnknown = start.litThroughGlass > 0 && !carriesLightThroughGlass(settings.method);
    if (settings.method == GridMethod::Preview)
        return computeGridByPreview(scene, points, normal, settings, ctx, onPass, std::move(start));
    if (settings.method != GridMethod::Path && settings.method != GridMethod::Vpl)
        return computeGridByBackend(scene, points, normal, settings, ctx, onPass, std::move(start));
    return computeGridByEstimator(scene, points, normal, settings, ctx, onPass, std::move(start));
}

GridResult computeSceneGrid(const SceneSnapshot& scene, const std::vector<V3d>& points, const V3d& normal,
                            const GridSettings& settings, TaskContext& ctx,
                            const std::function<void(const GridResult&)>& onPass) {
    // The camera is unused: a small film.
    const RenderScene renderScene(sceneAsRendered(scene), 16, 16, nullptr, settings.lightSelection);
    if (ctx.isCancelled() && !settings.processes) return {};
    return computeGridIlluminance(renderScene, points, normal, settings, ctx, onPass);
}

}  // namespace lucerna
