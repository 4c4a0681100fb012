#pragma once
// The primary sample space state of a Metropolis chain (Kelemen et al. 2002), as a sample
// generator: a tracer that draws its numbers from it samples the path that the chain's current
// point u in [0,1)^inf maps to, so that Metropolis light transport reuses the bidirectional
// sampler unchanged by swapping its generator (pbrt-v3's MLTSampler).
//
// The vector u grows lazily as the tracer asks for dimensions. A large step replaces every
// coordinate by a fresh uniform number; a small step moves each by a Gaussian of standard
// deviation sigma, wrapped around [0, 1) (symmetric, so the acceptance ratio is f(y) / f(x)).
// Coordinates are mutated when first read in an iteration; one left unread for n small steps
// catches up with a single Gaussian of sigma sqrt(n), which has the same distribution. reject()
// restores every coordinate the iteration changed. The coordinates are interleaved between the
// sample streams (camera, light, connection): stream s's k-th number is u[s + 3 k], so that a
// longer camera subpath does not shift the light subpath's numbers.

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
        replay_ = false;
        resetStreams();
    }
    // Begins a fresh uniform sample (the chain's first state): a large step, whatever the odds.
    void startLargeStep() {
        ++iteration_;
        largeStep_ = true;
        replay_ = false;
        resetStreams();
    }
    bool largeStep() const { return largeStep_; }

    void accept() {
        if (largeStep_) lastLargeStep_ = iteration_;
    }
    void reject() {
        for (Coordinate& c : u_)
            if (c.modified == iteration_) c.restore();
        --iteration_;
    }

    // Reads the current state again, unmutated (a coordinate not read since it last changed
    // first catches up with its pending steps, as a mutation reading it would have done). For
    // kernels that change some coordinates and evaluate the rest as they are.
    void startReplay() {
        replay_ = true;
        resetStreams();
    }
    // Writes the k-th number of a stream in the current state (a kernel's result), outside an
    // iteration.
    void setCoordinate(SampleStream stream, size_t k, float value) {
        Coordinate& c = at(coordinate(stream, k));
        catchUp(c);
        c.value = value;
    }
    // Sets the camera stream's numbers to u (the other streams' are drawn fresh when read), as
    // if a large step had drawn them and been accepted (tests start chains from exact samples of
    // a target).
    void setState(const std::vector<float>& u) {
        ++iteration_;
        u_.clear();
        for (size_t k = 0; k < u.size(); ++k) at(coordinate(SampleStream::Camera, k)) = Coordinate{u[k], u[k], iteration_, iteration_};
        lastLargeStep_ = iteration_;
        replay_ = false;
        resetStreams();
    }

    void beginStream(SampleStream s) override { stream_ = s; }

    float next1D() override {
        Coordinate& c = at(coordinate(stream_, streamIndex_[size_t(stream_)]++));
        if (replay_) {
            catchUp(c);
            return c.value;
        }
        // Untouched since the last accepted large step: it would have been drawn fresh then.
        if (c.modified < lastLargeStep_) {
            c.value = rng_.next1D();
            c.modified = lastLargeStep_;
        }
        c.backup();
        if (largeStep_) c.value = rng_.next1D();
        else smallStep(c, double(iteration_ - c.modified));
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

    static size_t coordinate(SampleStream s, size_t k) { return size_t(s) + size_t(kSampleStreams) * k; }

    Coordinate& at(size_t i) {
        if (i >= u_.size()) u_.resize(i + 1);
        return u_[i];
    }

    void resetStreams() {
        stream_ = SampleStream::Camera;
        for (size_t& k : streamIndex_) k = 0;
    }

    // `steps` small steps at once: a Gaussian of sigma sqrt(steps), wrapped into [0, 1).
    void smallStep(Coordinate& c, double steps) {
        c.value += float(gaussian() * sigma_ * std::sqrt(steps));
        c.value -= std::floor(c.value);
        if (c.value >= 1.0f) c.value = 0.0f;  // floor can round a tiny negative up to 1
    }

    // Brings a coordinate up to the current (accepted) iteration: fresh if the last large step
    // replaced it, else the small steps it missed.
    void catchUp(Coordinate& c) {
        if (c.modified < lastLargeStep_) {
            c.value = rng_.next1D();
            c.modified = lastLargeStep_;
        }
        if (c.modified < iteration_) {
            smallStep(c, double(iteration_ - c.modified));
            c.modified = iteration_;
        }
    }

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
    bool largeStep_ = true, replay_ = false;
    SampleStream stream_ = SampleStream::Camera;
    size_t streamIndex_[kSampleStreams] = {0, 0, 0};
};

}  // namespace lucerna
