#include "render/photometry/grid_combination.h"

#include "render/photometry/grid_statistics.h"

#include <cmath>
#include <limits>
#include <vector>

namespace lucerna {

namespace {

// A method's runs pooled at one point: the mean of all their pass means, its variance and 95% bar.
struct Pooled {
    double mean = 0, variance = 0, bar = 0;
    bool exact = false;
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
    p.bar = studentT975(dof) * std::sqrt(p.variance);
    return p;
}

}  // namespace

GridResult combineGridResults(std::span<const GridResult* const> parts, const GridSettings& settings) {
    if (parts.empty()) return {};
    GridResult out = *parts[0];
    // The methods' runs, the reference's first.
    std::vector<std::vector<const GridResult*>> methods;
    std::vector<GridMethod> names;
    for (const GridResult* p : parts) {
        if (!p || p->passes < kCombinedMinPasses) continue;
        size_t m = 0;
        while (m < names.size() && names[m] != p->method) ++m;
        if (m == names.size()) names.push_back(p->method), methods.emplace_back();
        methods[m].push_back(p);
    }
    if (methods.empty() || names[0] != parts[0]->method || (methods.size() == 1 && methods[0].size() == 1)) return out;
    out.passes = 0;
    out.samplesPerPoint = 0;
    for (const auto& runs : methods)
        for (const GridResult* r : runs) out.passes += r->passes, out.samplesPerPoint += r->samplesPerPoint;
    for (size_t i = 0; i < out.lux.size(); ++i) {
        std::vector<Pooled> pooled;
        for (const auto& runs : methods) pooled.push_back(poolRuns(runs, i));
        const Pooled& reference = pooled[0];
        double weights = 0, value = 0, bar = 0;
        bool exact = false;
        for (const Pooled& p : pooled) {
            if (p.exact) {
                out.lux[i] = p.mean, out.errorLux[i] = 0, exact = true;
                break;
            }
            if (std::abs(p.mean - reference.mean) > 3 * std::sqrt(p.variance + reference.variance)) continue;
            const double w = p.variance > 0 ? 1 / p.variance : 0.0;
            weights += w;
            value += w * p.mean;
            bar += w * w * p.bar * p.bar;
        }
        if (exact) continue;
        out.lux[i] = weights > 0 ? value / weights : reference.mean;
        out.errorLux[i] = weights > 0 ? std::sqrt(bar) / weights : reference.bar;
    }
    out.maxRelativeError = gridMaxRelativeError(out);
    out.converged = out.maxRelativeError <= settings.targetRelativeError;
    return out;
}

}  // namespace lucerna
