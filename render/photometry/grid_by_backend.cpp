// The bdpt, mir, mlt and cmlt grid methods: the backend renders the grid's points as irradiance
// sensors, in independent replicas whose spread gives the error bars (grid_calculation.h).

#include "render/photometry/grid_statistics.h"
#include "render/photometry/sensor_render.h"

#include <chrono>

namespace lucerna {

GridResult computeGridByBackend(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                const GridSettings& settings, TaskContext& ctx,
                                const std::function<void(const GridResult&)>& onPass, GridResult before) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    GridResult result = std::move(before);
    if (points.empty()) return result;

    const std::vector<IrradianceSensor> sensors = sensorsAt(points, normal);
    const std::map<std::string, std::string>& options = settings.backendOptions;
    const int replicaCount = std::max(2, settings.replicas);
    std::vector<std::unique_ptr<SensorRender>> replicas;
    for (int r = 0; r < replicaCount && !ctx.isCancelled(); ++r) {
        replicas.push_back(std::make_unique<SensorRender>(scene, gridMethodName(settings.method), sensors,
                                                          settings.sensorPixelsPerSide,
                                                          hashSeed(settings.seed, uint64_t(r), 0x67726964),
                                                          options));
        replicas.back()->prepare(ctx);
    }

    // Rounds of passes over every replica, each round doubled while it takes less than a tenth
    // of the time so far: the target is checked often enough that the time to reach it is known
    // within about 10%, and rarely enough that the checks cost nothing.
    int passesPerRound = 1;
    for (int pass = 0; !ctx.isCancelled();) {
        const auto roundStart = Clock::now();
        for (int k = 0; k < passesPerRound && !ctx.isCancelled(); ++k, ++pass)
            for (auto& r : replicas) r->renderPass(ctx, pass);
        if (ctx.isCancelled()) break;  // a partial pass would bias the replicas it missed

        std::vector<BatchMeans> means(points.size());
        for (const auto& r : replicas) {
            const std::vector<double> lux = r->lux();
            for (size_t i = 0; i < points.size(); ++i) means[i].add(lux[i]);
        }
        const auto now = Clock::now();
        result.passes = pass;
        result.samplesPerPoint = static_cast<long long>(pass) * replicas.front()->pixelsPerSensor() * replicaCount;
        result.seconds = std::chrono::duration<double>(now - start).count();
        if (finishRound(means, true, settings, ctx, result, onPass)) break;
        if (std::chrono::duration<double>(now - roundStart).count() < 0.1 * result.seconds) passesPerRound *= 2;
    }
    return result;
}

}  // namespace lucerna
