#pragma once
// The primary sample space state of a Metropolis chain (Kelemen et al. 2002), as a sample
// generator: a tracer that draws its numbers from it samples the path that the chain's current
// point u in [0,1)^inf maps to, so that Metropolis light transport reuses the bidirectional
// sampler unchanged by swapping its generator (pbrt-v3's MLTSampler, one stream).
//
// The vector u grows lazily as the tracer asks for dimensions. A large step replaces every
// coordinate by a fresh uniform number; a small step moves each by a Gaussian of standard
// deviation sigma, wrapped around [0, 1) (symmetric, so the acceptance ratio is f(y) / f(x)).
// Coordinates are mutated when first read in an iteration; one left unread for n small steps
// catches up with a single Gaussian of sigma sqrt(n), which has the same distribution. reject()
// restores every coordinate the iteration changed.

#include "render/trace/rng.h"
#include "render/trace/sample_generator.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace lucerna {

class PssSampler final : public SampleGenerator {
public:
    PssSampler(uint64_t seed, float sigma, float largeStepProbability)
        : rng_(seed, 0x6d6c74), sigma_(sigma), largeStepProbability_(largeStepProbability) {}

    // Begins a mutation: a large step with probability largeStepProbability, else a small one.
    void startIteration() {
        ++iteration_;
        largeStep_ = rng_.next1D() < largeStepProbability_;
        index_ = 0;
    }
    // Begins a fresh uniform sample (the chain's first state): a large step, whatever the odds.
    void startLargeStep() {
        ++iteration_;
        largeStep_ = true;
        index_ = 0;
    }
    bool largeStep() const { return largeStep_; }

    // Sets the state to u, as if a large step had drawn it and been accepted (tests start chains
    // from exact samples of a target).
    void setState(const std::vector<float>& u) {
        ++iteration_;
        u_.assign(u.size(), Coordinate{});
        for (size_t i = 0; i < u.size(); ++i) u_[i] = Coordinate{u[i], u[i], iteration_, iteration_};
        lastLargeStep_ = iteration_;
        index_ = 0;
    }

    void accept() {
        if (largeStep_) lastLargeStep_ = iteration_;
    }
    void reject() {
        for (Coordinate& c : u_)
            if (c.modified == iteration_) c.restore();
        --iteration_;
    }

    float next1D() override {
        const size_t i = index_++;
        if (i >= u_.size()) u_.resize(i + 1);
        Coordinate& c = u_[i];
        // Untouched since the last accepted large step: it would have been drawn fresh then.
        if (c.modified < lastLargeStep_) {
            c.value = rng_.next1D();
            c.modified = lastLargeStep_;
        }
        c.backup();
        if (largeStep_) {
            c.value = rng_.next1D();
        } else {
            const double steps = double(iteration_ - c.modified);
            c.value += float(gaussian() * sigma_ * std::sqrt(steps));
            c.value -= std::floor(c.value);
            if (c.value >= 1.0f) c.value = 0.0f;  // floor can round a tiny negative up to 1
        }
        c.modified = iteration_;
        return c.value;
    }
    V2f next2D() override {
        const float a = next1D();
        return V2f(a, next1D());
    }

    // Independent uniform numbers for the chain's own decisions (acceptance), not part of u.
    Rng& rng() { return rng_; }

private:
    struct Coordinate {
        float value = 0, savedValue = 0;
        int64_t modified = 0, savedModified = 0;
        void backup() {
            savedValue = value;
            savedModified = modified;
        }
        void restore() {
            value = savedValue;
            modified = savedModified;
        }
    };

    // Box-Muller: one standard normal number.
    double gaussian() {
        const double u1 = 1.0 - rng_.nextDouble();  // (0, 1]
        const double u2 = rng_.nextDouble();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }

    Rng rng_;
    float sigma_, largeStepProbability_;
    std::vector<Coordinate> u_;
    int64_t iteration_ = 0, lastLargeStep_ = 0;
    bool largeStep_ = true;
    size_t index_ = 0;
};

}  // namespace lucerna
