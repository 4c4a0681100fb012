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
//
// A stream step moves one stream's coordinates only (a Gaussian each, symmetric too) and leaves
// the others where they are: the primary-sample-space form of Veach's perturbations. Moving the
// light stream alone keeps the camera subpath and swings the light subpath around it, which is
// what a caustic perturbation does (a caustic's light path through glass onto a diffuse surface
// seen by the camera); the lazy catch-up counts the small steps each stream has taken.

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
        for (bool& m : moves_) m = !largeStep_;
        countSmallSteps(+1);
        replay_ = false;
        resetStreams();
    }
    // Begins a small step of stream `s` alone (the others keep their values).
    void startStreamStep(SampleStream s) {
        ++iteration_;
        largeStep_ = false;
        for (bool& m : moves_) m = false;
        moves_[size_t(s)] = true;
        countSmallSteps(+1);
        replay_ = false;
        resetStreams();
    }
    // Begins a fresh uniform sample (the chain's first state): a large step, whatever the odds.
    void startLargeStep() {
        ++iteration_;
        largeStep_ = true;
        for (bool& m : moves_) m = false;
        replay_ = false;
        resetStreams();
    }
    bool largeStep() const { return largeStep_; }

    void accept() {
        if (largeStep_) {
            lastLargeStep_ = iteration_;
            for (size_t s = 0; s < kSampleStreams; ++s) stepsAtLargeStep_[s] = streamSteps_[s];
        }
    }
    void reject() {
        for (Coordinate& c : u_)
            if (c.modified == iteration_) c.restore();
        countSmallSteps(-1);  // the proposal never happened, for unread coordinates too
        for (bool& m : moves_) m = false;
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
        catchUp(c, stream);
        c.value = value;
    }
    // Sets the camera stream's numbers to u (the other streams' are drawn fresh when read), as
    // if a large step had drawn them and been accepted (tests start chains from exact samples of
    // a target).
    void setState(const std::vector<float>& u) {
        ++iteration_;
        u_.clear();
        const int64_t steps = streamSteps_[size_t(SampleStream::Camera)];
        for (size_t k = 0; k < u.size(); ++k)
            at(coordinate(SampleStream::Camera, k)) = Coordinate{u[k], u[k], iteration_, iteration_, steps, steps};
        lastLargeStep_ = iteration_;
        for (size_t s = 0; s < kSampleStreams; ++s) stepsAtLargeStep_[s] = streamSteps_[s];
        replay_ = false;
        resetStreams();
    }

    void beginStream(SampleStream s) override { stream_ = s; }

    float next1D() override {
        const size_t s = size_t(stream_);
        Coordinate& c = at(coordinate(stream_, streamIndex_[s]++));
        if (replay_) {
            catchUp(c, stream_);
            return c.value;
        }
        freshIfBeforeLargeStep(c, s);
        c.backup();
        if (largeStep_) {
            c.value = rng_.next1D();
        } else if (const int64_t pending = streamSteps_[s] - c.steps; pending > 0) {
            smallStep(c, double(pending));  // this iteration's, if it moves the stream, and missed ones
        }
        c.modified = iteration_;
        c.steps = streamSteps_[s];
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
        int64_t modified = 0, savedModified = 0;  // the iteration that last set it
        int64_t steps = 0, savedSteps = 0;        // its stream's small-step count it has caught up with
        void backup() {
            savedValue = value;
            savedModified = modified;
            savedSteps = steps;
        }
        void restore() {
            value = savedValue;
            modified = savedModified;
            steps = savedSteps;
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

    // Untouched since the last accepted large step: it would have been drawn fresh then.
    void freshIfBeforeLargeStep(Coordinate& c, size_t s) {
        if (c.modified < lastLargeStep_) {
            c.value = rng_.next1D();
            c.modified = lastLargeStep_;
            c.steps = stepsAtLargeStep_[s];
        }
    }

    // Brings a coordinate up to the current (accepted) state: fresh if the last large step
    // replaced it, then the small steps of its stream it missed.
    void catchUp(Coordinate& c, SampleStream stream) {
        const size_t s = size_t(stream);
        freshIfBeforeLargeStep(c, s);
        if (const int64_t pending = streamSteps_[s] - c.steps; pending > 0) {
            smallStep(c, double(pending));
            c.steps = streamSteps_[s];
            c.modified = iteration_;
        }
    }

    // Adds (or takes back) this iteration's small step to the count of each stream it moves.
    void countSmallSteps(int delta) {
        for (size_t s = 0; s < kSampleStreams; ++s)
            if (moves_[s]) streamSteps_[s] += delta;
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
    int64_t streamSteps_[kSampleStreams] = {0, 0, 0};       // small steps that moved each stream
    int64_t stepsAtLargeStep_[kSampleStreams] = {0, 0, 0};  // the same, at the last accepted large step
    bool moves_[kSampleStreams] = {false, false, false};    // streams the current iteration moves
    bool largeStep_ = true, replay_ = false;
    SampleStream stream_ = SampleStream::Camera;
    size_t streamIndex_[kSampleStreams] = {0, 0, 0};
};

}  // namespace lucerna
