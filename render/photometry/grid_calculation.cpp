#include "render/photometry/grid_calculation.h"

#include "render/vpl/instant_radiosity.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace lucerna {

std::optional<GridMethod> gridMethodFromName(const std::string& name) {
    if (name == "path") return GridMethod::Path;
    if (name == "ir") return GridMethod::Vpl;
    return std::nullopt;
}

const char* gridMethodName(GridMethod method) { return method == GridMethod::Path ? "path" : "ir"; }

namespace {

// Running sums of a point's pass means.
struct BatchMeans {
    double sum = 0, sumSquares = 0;

    void add(double x) {
        sum += x;
        sumSquares += x * x;
    }
    double mean(int n) const { return n > 0 ? sum / n : 0.0; }
    // 1.96 standard errors of the mean of n batch means.
    double halfWidth95(int n) const {
        if (n < 2) return std::numeric_limits<double>::infinity();
        const double m = mean(n);
        const double variance = std::max(0.0, (sumSquares - n * m * m) / (n - 1));
        return 1.96 * std::sqrt(variance / n);
    }
};

double relativeError(double mean, double halfWidth) {
    if (halfWidth == 0) return 0;
    return mean > 0 ? halfWidth / mean : std::numeric_limits<double>::infinity();
}

}  // namespace

GridResult computeGridIlluminance(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                  const GridSettings& settings, TaskContext& ctx,
                                  const std::function<void(const GridResult&)>& onPass) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const IrradianceEstimator estimator(scene);
    const V3f n = V3f(float(normal.x), float(normal.y), float(normal.z)).normalized();
    const int count = int(points.size());
    std::vector<BatchMeans> batches(points.size());
    std::vector<double> passMean(points.size());
    GridResult result;
    result.lux.assign(points.size(), 0.0);
    result.errorLux.assign(points.size(), std::numeric_limits<double>::infinity());
    const int pointsPerTask = 16;
    const int samples =
        settings.samplesPerPass > 0 ? settings.samplesPerPass : settings.method == GridMethod::Path ? 16 : 1;

    for (int pass = 0; !ctx.isCancelled(); ++pass) {
        VplSet vpls;
        if (settings.method == GridMethod::Vpl)
            vpls = generateVpls(scene, settings.vplPathsPerPass, hashSeed(settings.seed, uint64_t(pass), 0x9d1));
        ctx.parallelFor(0, (count + pointsPerTask - 1) / pointsPerTask, [&](int task) {
            for (int i = task * pointsPerTask; i < std::min(count, (task + 1) * pointsPerTask); ++i) {
                const V3d& p = points[size_t(i)];
                const IrradianceSensor sensor{V3f(float(p.x), float(p.y), float(p.z)), n};
                Rng rng(hashSeed(settings.seed, uint64_t(pass)), uint64_t(i));
                double sum = 0;
                for (int s = 0; s < samples; ++s) {
                    const Rgb E = settings.method == GridMethod::Path ? estimator.samplePath(sensor, rng)
                                                                      : estimator.sampleVpl(sensor, rng, vpls);
                    if (isFinite(E)) sum += kLumensPerWatt * double(luminance(E));
                }
                passMean[size_t(i)] = sum / samples;
            }
        });
        if (ctx.isCancelled()) break;  // a partial pass would bias the points it missed

        result.passes = pass + 1;
        result.samplesPerPoint = static_cast<long long>(result.passes) * samples;
        result.maxRelativeError = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            batches[i].add(passMean[i]);
            result.lux[i] = batches[i].mean(result.passes);
            result.errorLux[i] = batches[i].halfWidth95(result.passes);
            result.maxRelativeError =
                std::max(result.maxRelativeError, relativeError(result.lux[i], result.errorLux[i]));
        }
        result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        result.converged =
            result.passes >= settings.minPasses && result.maxRelativeError <= settings.targetRelativeError;
        double progress = result.passes >= settings.minPasses && std::isfinite(result.maxRelativeError)
                              ? std::min(1.0, std::pow(settings.targetRelativeError / result.maxRelativeError, 2.0))
                              : 0.0;
        if (settings.timeLimitSeconds > 0)
            progress = std::max(progress, std::min(1.0, result.seconds / settings.timeLimitSeconds));
        ctx.setProgress(progress);
        if (onPass) onPass(result);
        if (result.converged) break;
        if (settings.timeLimitSeconds > 0 && result.seconds >= settings.timeLimitSeconds) break;
    }
    return result;
}

}  // namespace lucerna
