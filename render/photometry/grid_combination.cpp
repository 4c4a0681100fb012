#include "render/photometry/grid_combination.h"

#include "render/photometry/grid_statistics.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lucerna {

namespace {

// A method's variance at a point is taken as at least this share of its median ratio to the
// reference method's (varianceFloors).
constexpr double kVarianceFloor = 0.25;

// A method's runs pooled at one point: the mean of all their pass means, its variance and 95% bar.
struct Pooled {
    double mean = 0, variance = 0, quantile = 0;  // the bar: quantile x sqrt(variance)
    bool exact = false;
    double bar() const { return quantile * std::sqrt(variance); }
};

// The runs' estimates at point i pooled by passes (their per-pass variances pooled by degrees of
// freedom).
Pooled poolRuns(const std::vector<const GridResult*>& runs, size_t i) {
    double sum = 0, squares = 0;
    int passes = 0, dof = 0;
    for (const GridResult* r : runs) {
        if (r->errorLux[i] == 0) return {r->lux[i], 0, 0, true};
        const double sigma = r->errorLux[i] / studentT975(r->passes - 1);  // of r's mean
        sum += r->passes * r->lux[i];
        squares += (r->passes - 1) * sigma * sigma * r->passes;  // (n - 1) x the per-pass variance
        passes += r->passes;
        dof += r->passes - 1;
    }
    Pooled p;
    p.mean = sum / passes;
    p.variance = squares / dof / passes;
    p.quantile = studentT975(dof);
    return p;
}

// Per method, the least variance it may claim at a point, as a share of the reference method's
// there: kVarianceFloor times its median ratio to the reference's over the points (0 for the
// reference). A method that has met a rare contribution at a point less often than its share
// shows a spread there far below its usual one against the reference's, and would take the
// weight (the satin ball's caustic: ir's few paths through the glass).
std::vector<double> varianceFloors(const std::vector<std::vector<Pooled>>& pooled) {
    const size_t methods = pooled.empty() ? 0 : pooled[0].size();
    std::vector<double> floors(methods, 0.0);
    for (size_t m = 1; m < methods; ++m) {
        std::vector<double> ratios;
        for (const auto& point : pooled)
            if (!point[m].exact && !point[0].exact && point[0].variance > 0 && point[m].variance > 0)
                ratios.push_back(point[m].variance / point[0].variance);
        if (ratios.empty()) continue;
        std::ranges::nth_element(ratios, ratios.begin() + ratios.size() / 2);
        floors[m] = kVarianceFloor * ratios[ratios.size() / 2];
    }
    return floors;
}

}  // namespace

GridResult combineGridResults(std::span<const GridResult* const> parts, const GridSettings& settings) {
    if (parts.empty()) return {};
    GridResult out = *parts[0];
    // The methods' runs, the reference's first.
    struct MethodRuns {
        GridMethod method;
        std::vector<const GridResult*> runs;
    };
    std::vector<MethodRuns> methods;
    for (const GridResult* p : parts) {
        if (!p || p->passes < kCombinedMinPasses) continue;
        auto m = std::ranges::find(methods, p->method, &MethodRuns::method);
        if (m == methods.end()) m = methods.insert(methods.end(), {p->method, {}});
        m->runs.push_back(p);
    }
    if (methods.empty() || methods[0].method != parts[0]->method || (methods.size() == 1 && methods[0].runs.size() == 1))
        return out;
    out.passes = 0;
    out.samplesPerPoint = 0;
    for (const MethodRuns& m : methods)
        for (const GridResult* r : m.runs) out.passes += r->passes, out.samplesPerPoint += r->samplesPerPoint;
    std::vector<std::vector<Pooled>> pooled(out.lux.size());  // per point, per method
    for (size_t i = 0; i < out.lux.size(); ++i)
        for (const MethodRuns& m : methods) pooled[i].push_back(poolRuns(m.runs, i));
    const std::vector<double> floors = varianceFloors(pooled);
    for (size_t i = 0; i < out.lux.size(); ++i) {
        if (const auto exact = std::ranges::find_if(pooled[i], &Pooled::exact); exact != pooled[i].end()) {
            out.lux[i] = exact->mean, out.errorLux[i] = 0;
            continue;
        }
        const Pooled& reference = pooled[i][0];
        double weights = 0, value = 0, bar = 0;
        for (size_t m = 0; m < methods.size(); ++m) {
            const Pooled& p = pooled[i][m];
            if (std::abs(p.mean - reference.mean) > 3 * std::sqrt(p.variance + reference.variance)) continue;
            const double variance = std::max(p.variance, floors[m] * reference.variance);
            const double w = variance > 0 ? 1 / variance : 0.0;
            weights += w;
            value += w * p.mean;
            bar += w * w * p.quantile * p.quantile * variance;
        }
        out.lux[i] = weights > 0 ? value / weights : reference.mean;
        out.errorLux[i] = weights > 0 ? std::sqrt(bar) / weights : reference.bar();
    }
    out.maxRelativeError = gridMaxRelativeError(out);
    out.converged = out.maxRelativeError <= settings.targetRelativeError;
    return out;
}

}  // namespace lucerna
