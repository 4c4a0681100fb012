#include "render/photometry/grid_auto.h"

#include "core/number_format.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace lucerna {

namespace {

// 1 / (mean squared relative error x seconds) of a pilot's result: the error bars are 95%
// half-widths, relative to the point's value (at least a thousandth of the mean); points inside
// geometry left out. 0 when no error bar is known yet.
double efficiency(const GridResult& r) {
    double sum = 0, mean = 0;
    int n = 0;
    for (size_t i = 0; i < r.lux.size(); ++i)
        if (r.insideGeometry.empty() || !r.insideGeometry[i]) mean += std::max(0.0, r.lux[i]), ++n;
    if (n == 0 || !(r.seconds > 0)) return 0;
    mean /= n;
    for (size_t i = 0; i < r.lux.size(); ++i) {
        if (!r.insideGeometry.empty() && r.insideGeometry[i]) continue;
        const double e = r.errorLux[i] / 1.96 / std::max(std::abs(r.lux[i]), 1e-3 * mean + 1e-300);
        if (!std::isfinite(e)) return 0;
        sum += e * e;
    }
    return sum > 0 ? 1.0 / (sum / n * r.seconds) : 0.0;
}

}  // namespace

GridAutoChoice chooseGridMethod(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal,
                                const GridSettings& settings, bool litThroughGlass, TaskContext& ctx) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<GridMethod> alive = litThroughGlass ? std::vector{GridMethod::Bdpt, GridMethod::Mlt, GridMethod::Cmlt}
                                                    : std::vector{GridMethod::Path, GridMethod::Vpl, GridMethod::Bdpt,
                                                                  GridMethod::Mir, GridMethod::Mlt, GridMethod::Cmlt};
    std::vector<double> measured(alive.size(), 0.0);
    const std::vector<GridMethod> all = alive;
    double round = settings.timeLimitSeconds > 0 ? std::max(0.1, 0.02 * settings.timeLimitSeconds) : 0.2;
    GridAutoChoice choice;
    choice.method = alive.front();
    for (int r = 0; r < 4 && alive.size() > 1 && !ctx.isCancelled(); ++r, round *= 2) {
        std::vector<double> eff;
        for (GridMethod m : alive) {
            GridSettings pilot = settings;
            pilot.autoMethod = false;
            pilot.method = m;
            pilot.timeLimitSeconds = round;
            pilot.seed = settings.seed + 0x70696c6f + uint64_t(r);
            GridResult result = computeGridIlluminance(scene, points, normal, pilot, ctx);
            eff.push_back(efficiency(result));
            measured[size_t(std::ranges::find(all, m) - all.begin())] = eff.back();
            if (ctx.isCancelled()) return {GridMethod::Path, {}, "", 0};
            if (result.converged) {
                choice.method = m;
                choice.finished = std::move(result);
                break;
            }
        }
        if (choice.finished) break;
        const double best = *std::ranges::max_element(eff);
        // The next round runs the survivors best first: the leader is the likeliest to reach the
        // target within its pilot, which then ends the choice before the others' rounds.
        std::vector<size_t> order;
        for (size_t i = 0; i < alive.size(); ++i)
            if (eff[i] >= 0.25 * best && best > 0) order.push_back(i);
        std::ranges::stable_sort(order, [&](size_t a, size_t b) { return eff[a] > eff[b]; });
        choice.method = alive[size_t(std::ranges::max_element(eff) - eff.begin())];
        if (order.empty()) continue;
        std::vector<GridMethod> next;
        for (size_t i : order) next.push_back(alive[i]);
        alive = next;
    }
    choice.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double best = *std::ranges::max_element(measured);
    choice.measured = "pilots (efficiency, best 1):";
    for (size_t i = 0; i < all.size(); ++i)
        choice.measured += std::string(i ? ", " : " ") + gridMethodName(all[i]) + " " +
                           formatNumber(best > 0 ? measured[i] / best : 0.0, 2);
    choice.measured += "; " + formatDuration(choice.seconds) + "; chose " + gridMethodName(choice.method) +
                       (choice.finished ? ", whose pilot reached the target" : "");
    return choice;
}

}  // namespace lucerna
