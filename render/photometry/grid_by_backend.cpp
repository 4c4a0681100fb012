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
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    GridResult result = std::move(before);
    if (points.empty()) return result;

    const std::vector<IrradianceSensor> sensors = sensorsAt(points, normal);
    const std::map<std::string, std::string>& options = settings.backendOptions;
    const int replicaCount = std::max(2, settings.replicas);
    // Shared among processes, each makes the replicas it owns (replica r's seed is r's wherever
    // it runs), and every process goes round until all agree to stop.
    const bool shared = sizeOf(settings.processes) > 1;
    std::vector<std::unique_ptr<SensorRender>> replicas(static_cast<size_t>(replicaCount));
    for (int r = 0; r < replicaCount && !ctx.isCancelled(); ++r) {
        if (!ownsBlock(settings.processes, r)) continue;
        replicas[size_t(r)] = std::make_unique<SensorRender>(scene, gridMethodName(settings.method), sensors,
                                                             settings.sensorPixelsPerSide,
                                                             hashSeed(settings.seed, uint64_t(r), 0x67726964), options);
        replicas[size_t(r)]->prepare(ctx);
    }

    // Rounds of passes over every replica, each round doubled while it takes less than a tenth
    // of the time so far: the target is checked often enough that the time to reach it is known
    // within about 10%, and rarely enough that the checks cost nothing.
    int passesPerRound = 1;
    const int pixelsPerSensor = settings.sensorPixelsPerSide * settings.sensorPixelsPerSide;
    for (int pass = 0; shared || !ctx.isCancelled();) {
        const auto roundStart = Clock::now();
        for (int k = 0; k < passesPerRound && !ctx.isCancelled(); ++k, ++pass)
            for (auto& r : replicas)
                if (r) r->renderPass(ctx, pass);
        // Every replica's values, in replica order (0 for another process's).
        std::vector<double> values(size_t(replicaCount) * points.size(), 0.0);
        for (int r = 0; r < replicaCount && !ctx.isCancelled(); ++r)
            if (replicas[size_t(r)]) {
                const std::vector<double> lux = replicas[size_t(r)]->lux();
                std::copy(lux.begin(), lux.end(), values.begin() + std::ptrdiff_t(size_t(r) * points.size()));
            }
        const auto now = Clock::now();
        std::vector<double> maxima{std::chrono::duration<double>(now - start).count(),
                                   std::chrono::duration<double>(now - roundStart).count(), ctx.isCancelled() ? 1.0 : 0.0};
        shareRound(settings.processes, values, maxima);
        if (maxima[2] > 0) break;  // a partial pass would bias the replicas it missed

        std::vector<BatchMeans> means(points.size());
        for (int r = 0; r < replicaCount; ++r)
            for (size_t i = 0; i < points.size(); ++i) means[i].add(values[size_t(r) * points.size() + i]);
        result.passes = pass;
        result.samplesPerPoint = static_cast<long long>(pass) * pixelsPerSensor * replicaCount;
        result.seconds = maxima[0];
        if (finishRound(means, true, settings, ctx, result, onPass)) break;
        if (maxima[1] < 0.1 * result.seconds) passesPerRound *= 2;
    }
    return result;
}

}  // namespace lucerna
