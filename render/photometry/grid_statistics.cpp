#include "render/photometry/grid_statistics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace lucerna {

double studentT975(int dof) {
    static constexpr double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                        2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086};
    if (dof < 1) return std::numeric_limits<double>::infinity();
    if (dof <= 20) return kTable[dof - 1];
    return 1.96 + 2.4 / dof;  // within 0.3% of the quantile beyond 20 degrees of freedom
}

double BatchMeans::halfWidth95() const {
    if (count < 2) return std::numeric_limits<double>::infinity();
    const double m = mean();
    const double variance = std::max(0.0, (sumSquares - count * m * m) / (count - 1));
    return studentT975(count - 1) * std::sqrt(variance / count);
}

namespace {
// The error bar relative to the point's value, or to a thousandth of the grid's average for a
// point darker than that: a point inside a closed cabinet, whose true value is 0, measures
// leaks of a millionth of the average (rays slipping through the seam where a box stands on the
// floor) and would never reach 2% of itself; nobody reads its value that closely.
double relativeError(double mean, double halfWidth, double floor) {
    if (halfWidth == 0) return 0;
    const double scale = std::max(mean, floor);
    return scale > 0 ? halfWidth / scale : std::numeric_limits<double>::infinity();
}

// The end of a round shared among processes: each gives the values of what it owns (0
// elsewhere) in `sums` and its own figures in `maxima` (times so far, 1 when cancelled); every
// one gets back the sums over the processes and the maxima, so that all decide alike. Nothing
// changes when `processes` is nullptr.
void shareRound(ProcessGroup* processes, std::vector<double>& sums, std::vector<double>& maxima) {
    if (!processes || processes->size() == 1) return;
    std::vector<double> mine = sums;
    mine.insert(mine.end(), maxima.begin(), maxima.end());
    const std::vector<double> all = processes->allGather(mine);
    const size_t n = mine.size();
    for (int r = 0; r < processes->size(); ++r) {
        const double* theirs = all.data() + size_t(r) * n;
        for (size_t i = 0; i < sums.size(); ++i) sums[i] = r == 0 ? theirs[i] : sums[i] + theirs[i];
        for (size_t i = 0; i < maxima.size(); ++i)
            maxima[i] = r == 0 ? theirs[sums.size() + i] : std::max(maxima[i], theirs[sums.size() + i]);
    }
}
}  // namespace

GridResult emptyGridResult(size_t points, const std::vector<uint8_t>& insideGeometry) {
    GridResult r;
    r.insideGeometry = insideGeometry;
    r.insideGeometry.resize(points, 0);
    r.lux.assign(points, 0.0);
    r.errorLux.assign(points, std::numeric_limits<double>::infinity());
    return r;
}

std::vector<IrradianceSensor> sensorsAt(const std::vector<V3d>& points, const V3d& normal) {
    const V3f n = toFloat(normal).normalized();
    std::vector<IrradianceSensor> sensors;
    sensors.reserve(points.size());
    for (const V3d& p : points) sensors.push_back({toFloat(p), n});
    return sensors;
}

std::vector<IrradianceSensor> cylinderSensorsAt(const std::vector<V3d>& points, const V3d& axis, float offsetRadians) {
    const Frame frame(toFloat(axis).normalized());
    std::vector<IrradianceSensor> sensors;
    sensors.reserve(4 * points.size());
    for (const V3d& p : points)
        for (int k = 0; k < 4; ++k)
            sensors.push_back({toFloat(p), azimuthDirection(frame, offsetRadians + float(k) * 0.5f * kPi)});
    return sensors;
}

std::vector<double> cylindricalDeltaLux(const RenderScene& scene, const std::vector<V3d>& points, const V3d& axis,
                                        bool throughPanes) {
    const IrradianceEstimator estimator(scene);
    std::vector<double> lux;
    lux.reserve(points.size());
    for (const V3d& p : points)
        lux.push_back(kLumensPerWatt *
                      double(luminance(estimator.deltaLightsCylindrical(toFloat(p), toFloat(axis), throughPanes))));
    return lux;
}

double gridMaxRelativeError(const GridResult& r) {
    const auto counted = [&](size_t i) { return i >= r.insideGeometry.size() || !r.insideGeometry[i]; };
    double sum = 0;
    int count = 0;
    for (size_t i = 0; i < r.lux.size(); ++i)
        if (counted(i)) sum += std::max(0.0, r.lux[i]), ++count;
    const double average = count > 0 ? sum / count : 0.0;
    double worst = 0;
    for (size_t i = 0; i < r.lux.size(); ++i)
        if (counted(i)) worst = std::max(worst, relativeError(r.lux[i], r.errorLux[i], 1e-3 * average));
    return worst;
}

bool finishRound(const std::vector<BatchMeans>& points, bool trusted, const GridSettings& settings, TaskContext& ctx,
                 GridResult& result, const std::function<void(const GridResult&)>& onPass) {
    result.lux.resize(points.size());
    result.errorLux.resize(points.size());
    result.insideGeometry.resize(points.size(), 0);
    for (size_t i = 0; i < points.size(); ++i) {
        result.lux[i] = points[i].mean();
        result.errorLux[i] = points[i].halfWidth95();
    }
    result.maxRelativeError = gridMaxRelativeError(result);
    result.converged = trusted && result.maxRelativeError <= settings.targetRelativeError;
    double progress = trusted && std::isfinite(result.maxRelativeError)
                          ? std::min(1.0, std::pow(settings.targetRelativeError / result.maxRelativeError, 2.0))
                          : 0.0;
    if (settings.timeLimitSeconds > 0)
        progress = std::max(progress, std::min(1.0, result.seconds / settings.timeLimitSeconds));
    ctx.setProgress(progress);
    if (onPass) onPass(result);
    return result.converged || (settings.timeLimitSeconds > 0 && result.seconds >= settings.timeLimitSeconds);
}

void runRounds(const GridSettings& settings, TaskContext& ctx, std::chrono::steady_clock::time_point start,
               RoundValues kind, const std::function<std::vector<double>(int first, int passes)>& round,
               const std::function<bool(const std::vector<double>& values, int first, int passes, double seconds)>& take) {
    using Clock = std::chrono::steady_clock;
    const bool shared = sizeOf(settings.processes) > 1;
    const bool grows = shared || kind == RoundValues::EachRound;
    constexpr int kMaxPassesPerRound = 256;
    for (int first = 0, passes = 1; shared || !ctx.isCancelled();) {
        const auto roundStart = Clock::now();
        std::vector<double> values = round(first, passes);
        const auto now = Clock::now();
        std::vector<double> maxima{std::chrono::duration<double>(now - start).count(),
                                   std::chrono::duration<double>(now - roundStart).count(), ctx.isCancelled() ? 1.0 : 0.0};
        shareRound(settings.processes, values, maxima);
        if (maxima[2] > 0 || take(values, first, passes, maxima[0])) return;
        first += passes;
        if (grows && maxima[1] < 0.1 * maxima[0]) passes = std::min(kMaxPassesPerRound, 2 * passes);
    }
}

void runPointPasses(size_t points, int samplesPerPass, const GridSettings& settings, TaskContext& ctx,
                    const std::function<void(int pass, std::span<double> values)>& pass,
                    const std::function<void(const GridResult&)>& onPass, GridResult& result) {
    std::vector<BatchMeans> batches(points);
    runRounds(
        settings, ctx, std::chrono::steady_clock::now(), RoundValues::EachPass,
        [&](int first, int passes) {
            std::vector<double> values(size_t(passes) * points, 0.0);  // pass by pass
            for (int k = 0; k < passes && !ctx.isCancelled(); ++k)
                pass(first + k, std::span(values).subspan(size_t(k) * points, points));
            return values;
        },
        [&](const std::vector<double>& values, int first, int passes, double seconds) {
            for (int k = 0; k < passes; ++k) {
                for (size_t i = 0; i < points; ++i) batches[i].add(values[size_t(k) * points + i]);
                result.passes = first + k + 1;
                result.samplesPerPoint = static_cast<long long>(result.passes) * samplesPerPass;
                result.seconds = seconds;
                if (finishRound(batches, result.passes >= settings.minPasses, settings, ctx, result, onPass)) return true;
            }
            return false;
        });
}

}  // namespace lucerna
