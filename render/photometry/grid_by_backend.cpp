// The bdpt, mir, mlt and cmlt grid methods: the backend renders the grid's points as irradiance
// sensors, in independent replicas whose spread gives the error bars (grid_calculation.h).

#include "render/photometry/grid_statistics.h"
#include "render/photometry/sensor_render.h"

#include <algorithm>
#include <chrono>

namespace lucerna {

GridResult computeGridByBackend(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                const GridSettings& settings, TaskContext& ctx,
                                const std::function<void(const GridResult&)>& onPass, GridResult before) {
    const auto start = std::chrono::steady_clock::now();  // the replicas' preparation counts
    GridResult result = std::move(before);
    if (points.empty()) return result;

    // The cylinder: four vertical sensors a point, turned by a random azimuth per replica, their
    // mean without the delta lights plus the delta lights' exact cylindrical part.
    const bool cylindrical = settings.quantity == GridQuantity::Cylindrical;
    const int sensorsPerPoint = cylindrical ? 4 : 1;
    const std::vector<double> cylinderDeltaLux =
        cylindrical ? cylindricalDeltaLux(scene, points, normal, /*throughPanes=*/true) : std::vector<double>{};
    const std::map<std::string, std::string>& options = settings.backendOptions;
    const int replicaCount = std::max(2, settings.replicas);
    // Shared among processes, each makes the replicas it owns (replica r's seed is r's wherever
    // it runs).
    std::vector<std::unique_ptr<SensorRender>> replicas(static_cast<size_t>(replicaCount));
    for (int r = 0; r < replicaCount && !ctx.isCancelled(); ++r) {
        if (!ownsBlock(settings.processes, r)) continue;
        const uint64_t seed = hashSeed(settings.seed, uint64_t(r), 0x67726964);
        const std::vector<IrradianceSensor> sensors =
            cylindrical ? cylinderSensorsAt(points, normal, 0.5f * kPi * Rng(seed, 0x617a).next1D())
                        : sensorsAt(points, normal);
        replicas[size_t(r)] = std::make_unique<SensorRender>(scene, gridMethodName(settings.method), sensors,
                                                             settings.sensorPixelsPerSide,
                                                             seed, options);
        replicas[size_t(r)]->prepare(ctx);
    }
    result.prepareSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // Rounds of passes over every replica, their values read once a round. Cancellation is
    // checked before each replica's pass (a cancelled round is dropped whole): a round of eight
    // replicas may take a quarter of a second, and a pilot cut at its deadline (grid_auto.h)
    // would otherwise run all of it (mir on the glass partition office: 0.4 s against 0.17 s).
    const int pixelsPerSensor = settings.sensorPixelsPerSide * settings.sensorPixelsPerSide;
    runRounds(
        settings, ctx, start, RoundValues::EachRound,
        [&](int first, int passes) {
            for (int k = 0; k < passes && !ctx.isCancelled(); ++k)
                for (auto& r : replicas)
                    if (r && !ctx.isCancelled()) r->renderPass(ctx, first + k);
            // Every replica's values, in replica order (0 for another process's).
            std::vector<double> values(size_t(replicaCount) * points.size(), 0.0);
            for (int r = 0; r < replicaCount && !ctx.isCancelled(); ++r)
                if (replicas[size_t(r)]) {
                    const std::vector<double> lux = replicas[size_t(r)]->lux(/*withDeltaLights=*/!cylindrical);
                    for (size_t i = 0; i < points.size(); ++i) {
                        double& value = values[size_t(r) * points.size() + i];
                        for (int k = 0; k < sensorsPerPoint; ++k) value += lux[i * size_t(sensorsPerPoint) + size_t(k)];
                        value /= sensorsPerPoint;
                        if (cylindrical) value += cylinderDeltaLux[i];
                    }
                }
            return values;
        },
        [&](const std::vector<double>& values, int first, int passes, double seconds) {
            std::vector<BatchMeans> means(points.size());
            for (int r = 0; r < replicaCount; ++r)
                for (size_t i = 0; i < points.size(); ++i) means[i].add(values[size_t(r) * points.size() + i]);
            result.passes = first + passes;
            result.samplesPerPoint =
                static_cast<long long>(result.passes) * pixelsPerSensor * sensorsPerPoint * replicaCount;
            result.seconds = seconds;
            return finishRound(means, true, settings, ctx, result, onPass);
        });
    return result;
}

}  // namespace lucerna
