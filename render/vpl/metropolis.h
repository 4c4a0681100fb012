#pragma once
// A Metropolis-Hastings chain in primary sample space [0,1)^D (Kelemen et al. 2002) with
// multiple-try steps (Liu, Liang & Wong 2000), whose stationary density is proportional to a
// target f >= 0. Used by Metropolis instant radiosity (Segovia et al. 2007) to sample
// camera-to-light paths in proportion to their image contribution; tested on a 2D target.
//
// One step with T symmetric (so the MTM weight w(y, x) = f(y) T(x, y) reduces to f(y)):
//   1. choose the kernel T for this step: a large step (uniform, independent of x) with
//      probability largeStepProbability, else a small step (Kelemen's exponential perturbation of
//      every coordinate, wrapped around: symmetric);
//   2. draw k trials y_1..y_k ~ T(x, .) and evaluate f(y_j);
//   3. select y = y_J with probability f(y_J) / sum_j f(y_j);
//   4. draw the reference set x*_1..x*_{k-1} ~ T(y, .), and x*_k = x;
//   5. accept y with probability min(1, sum_j f(y_j) / sum_j f(x*_j)).
// With k = 1 this is plain Metropolis-Hastings (accept with min(1, f(y)/f(x))). Choosing the kernel
// independently of the state keeps each step's kernel a valid MTM kernel, so the mixture leaves the
// target invariant.
//
// Every evaluation at a point drawn uniformly and independently of the chain (large-step trials
// and references, and the start candidates) is also an independent sample of f under the uniform
// density: their mean is an unbiased estimate of the normalisation integral of f, which the
// caller reads with uniformMean().

#include "render/trace/rng.h"

#include <cmath>
#include <functional>
#include <vector>

namespace lucerna {

struct MetropolisParams {
    int dimension = 2;
    int tries = 1;                      // k: trials per step (1: plain Metropolis-Hastings)
    float largeStepProbability = 0.3f;  // in [0, 1]
    float smallStepMin = 1.0f / 1024.0f, smallStepMax = 1.0f / 64.0f;  // Kelemen's s1, s2
};

template <class Payload>
class MultipleTryMetropolis {
public:
    // f(u, payload) >= 0; fills the payload of the point it evaluates (what the caller needs
    // from an accepted state, e.g. the path). Must be finite.
    using Target = std::function<double(const std::vector<float>& u, Payload& payload)>;

    MultipleTryMetropolis(const MetropolisParams& params, Target target)
        : params_(params), target_(std::move(target)), state_(size_t(params.dimension), 0.5f) {}

    // Starts the chain by importance resampling: `candidates` uniform points, one kept with
    // probability proportional to f. Returns false when f is 0 at all of them (the chain has no
    // state yet; call again later).
    bool start(Rng& rng, int candidates) {
        std::vector<float> u(state_.size());
        Payload p;
        double sum = 0;
        for (int i = 0; i < candidates; ++i) {
            fillUniform(rng, u);
            const double f = evaluateUniform(u, p);
            if (f <= 0) continue;
            sum += f;
            if (rng.nextDouble() * sum < f) {  // reservoir sampling, proportional to f
                state_ = u;
                value_ = f;
                payload_ = p;
            }
        }
        started_ = sum > 0;
        return started_;
    }

    // Sets the state directly (tests start chains from exact samples of the target).
    void setState(const std::vector<float>& u) {
        state_ = u;
        value_ = target_(state_, payload_);
        started_ = true;
    }

    // One multiple-try step; returns true when the chain moved.
    bool step(Rng& rng) {
        ++steps_;
        const bool large = rng.next1D() < params_.largeStepProbability;
        const int k = std::max(1, params_.tries);
        trials_.resize(size_t(k));
        trialValues_.resize(size_t(k));
        trialPayloads_.resize(size_t(k));
        double trialSum = 0;
        for (int j = 0; j < k; ++j) {
            propose(rng, large, state_, trials_[size_t(j)]);
            trialValues_[size_t(j)] = evaluate(large, trials_[size_t(j)], trialPayloads_[size_t(j)]);
            trialSum += trialValues_[size_t(j)];
        }
        if (!(trialSum > 0)) return false;
        const size_t chosen = selectProportional(rng, trialValues_, trialSum);

        double referenceSum = value_;  // x*_k = x
        std::vector<float> reference(state_.size());
        Payload scratch;
        for (int j = 0; j + 1 < k; ++j) {
            propose(rng, large, trials_[chosen], reference);
            referenceSum += evaluate(large, reference, scratch);
        }
        const double acceptance = referenceSum > 0 ? std::min(1.0, trialSum / referenceSum) : 1.0;
        if (rng.nextDouble() >= acceptance) return false;
        state_.swap(trials_[chosen]);
        value_ = trialValues_[chosen];
        payload_ = std::move(trialPayloads_[chosen]);
        ++accepted_;
        return true;
    }

    bool started() const { return started_; }
    const std::vector<float>& state() const { return state_; }
    double value() const { return value_; }
    const Payload& payload() const { return payload_; }

    double acceptanceRate() const { return steps_ > 0 ? double(accepted_) / double(steps_) : 0.0; }
    // Mean of f over every uniform, chain-independent evaluation so far (0 before any).
    double uniformMean() const { return uniformCount_ > 0 ? uniformSum_ / double(uniformCount_) : 0.0; }
    long long uniformCount() const { return uniformCount_; }

private:
    static void fillUniform(Rng& rng, std::vector<float>& u) {
        for (float& x : u) x = rng.next1D();
    }

    double evaluateUniform(const std::vector<float>& u, Payload& p) {
        const double f = target_(u, p);
        uniformSum_ += f;
        ++uniformCount_;
        return f;
    }

    double evaluate(bool large, const std::vector<float>& u, Payload& p) {
        return large ? evaluateUniform(u, p) : target_(u, p);
    }

    // Kelemen et al. 2002: each coordinate moves by +-s2 exp(-log(s2/s1) r), wrapped into [0, 1).
    void propose(Rng& rng, bool large, const std::vector<float>& from, std::vector<float>& to) const {
        to.resize(from.size());
        if (large) {
            fillUniform(rng, to);
            return;
        }
        const float logRatio = std::log(params_.smallStepMax / params_.smallStepMin);
        for (size_t i = 0; i < from.size(); ++i) {
            const float r = rng.next1D();
            const float dv = params_.smallStepMax * std::exp(-logRatio * rng.next1D());
            float x = from[i] + (r < 0.5f ? dv : -dv);
            x -= std::floor(x);
            to[i] = x < 1.0f ? x : 0.0f;  // floor can round a tiny negative up to exactly 1
        }
    }

    static size_t selectProportional(Rng& rng, const std::vector<double>& w, double sum) {
        double target = rng.nextDouble() * sum;
        for (size_t j = 0; j < w.size(); ++j) {
            if (target < w[j]) return j;
            target -= w[j];
        }
        for (size_t j = w.size(); j-- > 0;)
            if (w[j] > 0) return j;  // rounding at the end of the sum
        return 0;
    }

    MetropolisParams params_;
    Target target_;
    std::vector<float> state_;
    double value_ = 0;
    Payload payload_{};
    bool started_ = false;
    std::vector<std::vector<float>> trials_;
    std::vector<double> trialValues_;
    std::vector<Payload> trialPayloads_;
    long long steps_ = 0, accepted_ = 0;
    double uniformSum_ = 0;
    long long uniformCount_ = 0;
};

}  // namespace lucerna
