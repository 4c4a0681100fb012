#include "render/vpl/mir_chain.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

MirChain::MirChain(const RenderScene& scene, const LightSampler& lights, const Sensor& camera,
                   const MirChainSettings& settings, float maxG, uint64_t seed)
    : scene_(scene), lights_(lights), settings_(settings), maxG_(maxG), dimension_(mirPathDimension(settings.vpl)),
      rng_(seed, 0x4d495243) {
    points_ = traceImportancePoints(scene, camera, settings.maxSpecularDepth, settings.importancePoints,
                                    hashSeed(seed, 0x53));
    floor_ = defensiveFloor();
    MetropolisParams params;
    params.dimension = dimension_;
    params.tries = settings.tries;
    params.largeStepProbability = settings.largeStepProbability;
    mtm_ = std::make_unique<MultipleTryMetropolis<MirPath>>(
        params, [this](const std::vector<float>& u, MirPath& path) { return target(floor_, u, path); });
}

double MirChain::target(double floor, const std::vector<float>& u, MirPath& path) const {
    return evaluateMirLightPath(scene_, lights_, points_, settings_.vpl, maxG_, floor, u, path);
}

double MirChain::defensiveFloor() {
    std::vector<float> u(static_cast<size_t>(dimension_));
    MirPath path;
    double sum = 0;
    long long vertices = 0;
    for (int i = 0; i < settings_.pilotPaths; ++i) {
        for (float& x : u) x = rng_.next1D();
        sum += target(0.0, u, path);
        vertices += static_cast<long long>(path.vpls.size());
    }
    const double mean = vertices > 0 ? sum / double(vertices) : 0.0;
    return mean > 0 && std::isfinite(mean) ? settings_.defensive * mean : 1.0;
}

double MirChain::pc() const {
    const double exactCount = double(mtm_->uniformCount());
    const double count = exactCount + double(cheapCount_);
    return count > 0 ? (mtm_->uniformMean() * exactCount + cheapSum_) / count : 0.0;
}

double MirChain::pcSampleRelativeVariance() const {
    if (cheapCount_ < 2) return 0;
    const double n = double(cheapCount_), mean = cheapSum_ / n, pc = this->pc();
    const double variance = std::max(0.0, cheapSumSquares_ / n - mean * mean) * n / (n - 1);
    return pc > 0 ? variance / (pc * pc) : 0.0;
}

double MirChain::pcRelativeVariance() const {
    const double count = double(mtm_->uniformCount() + cheapCount_);
    return count > 0 ? pcSampleRelativeVariance() / count : 0.0;
}

double MirChain::pcSampleRays() const {
    return cheapCount_ > 0 ? double(cheapVertices_) / double(cheapCount_) * (1 + settings_.pcPointsPerVertex) : 0.0;
}

VplSet MirChain::sampleVpls(int n) {
    VplSet vpls = sampleUnitVpls(n);
    const float pc = float(this->pc());
    VplSet weighted;
    for (Vpl v : vpls) {
        v.power *= pc;
        if (isFinite(v.power) && !isBlack(v.power)) weighted.push_back(v);
    }
    return weighted;
}

VplSet MirChain::sampleUnitVpls(int n) {
    VplSet vpls;
    if (n <= 0 || (!mtm_->started() && !mtm_->start(rng_, settings_.startCandidates))) return vpls;
    for (int i = 0; i < settings_.pcSamples; ++i) {
        int vertices = 0;
        const double f = estimateMirImportance(scene_, lights_, points_, settings_.vpl, maxG_, floor_,
                                               settings_.pcPointsPerVertex, rng_, &vertices);
        cheapSum_ += f;
        cheapSumSquares_ += f * f;
        cheapVertices_ += vertices;
    }
    cheapCount_ += settings_.pcSamples;
    std::vector<int> counts;
    std::vector<double> importance;
    for (int i = 0; i < n; ++i) {
        const bool moved = mtm_->step(rng_);
        if (moved || chosen_ < 0 || vpls.empty()) {
            if (moved || chosen_ < 0) chosen_ = choosePathVertex(mtm_->payload(), rng_.nextDouble());
            if (chosen_ < 0) continue;
            vpls.push_back(mtm_->payload().vpls[size_t(chosen_)]);
            importance.push_back(mtm_->payload().contribution[size_t(chosen_)]);
            counts.push_back(1);
        } else {
            ++counts.back();  // a rejected step: the same path VPL again
        }
    }
    VplSet weighted;
    for (size_t i = 0; i < vpls.size(); ++i) {
        const double w = double(counts[i]) / (double(n) * importance[i]);
        if (!(w > 0) || !std::isfinite(w)) continue;
        Vpl v = vpls[i];
        v.power *= float(w);
        if (isFinite(v.power) && !isBlack(v.power)) weighted.push_back(v);
    }
    return weighted;
}

}  // namespace lucerna
