#pragma once
// The per-thread part of the mlt backend: one Markov chain in primary sample space (Kelemen et
// al. 2002) driving the bidirectional sampler of the bdpt backend through a PssSampler.
//
// A point u maps to a raster point over the whole image (its first two numbers) and one BDPT
// sample there: the camera strategies' radiance at that pixel plus the light-tracing splats.
// Together they are the sample's contribution C(u), a small list of pixel deposits, and the
// chain's target is f(u) = the sum of their luminances. With b = int f du (the bootstrap
// estimate), a chain distributed as f / b estimates the image as
//   I = (W H / M) sum over M mutations of (b / f(u)) C(u),
// and each step deposits the proposal and the current state by their expected values
// (Veach 1997, section 11.5): C(y) a / f(y) and C(x) (1 - a) / f(x), a = min(1, f(y) / f(x)).
// b multiplies the film half at read-out (Film::setHalfScale), so that its refinement by the large
// steps reaches every pass.

#include "render/progressive/bdpt/bdpt_tracer.h"
#include "render/progressive/mlt/mlt_settings.h"
#include "render/trace/pss_sampler.h"

#include <vector>

namespace lucerna {

// What one point of primary sample space brings to the film.
struct PathContribution {
    std::vector<FilmSplat> deposits;  // the camera sample at its pixel and the light splats
    double f = 0;                     // sum of their luminances: the chain's target
};

// Evaluates the BDPT sample that `sampler`'s current iteration maps to.
void evaluatePath(BdptTracer& tracer, const PinholeCamera& camera, PssSampler& sampler, PathContribution& out);

class MltChain {
public:
    // A chain whose first state is the bootstrap sample drawn with seed `bootstrapSeed` (the
    // sampler's first large step replays it exactly).
    MltChain(const RenderScene& scene, const MltSettings& settings, uint64_t bootstrapSeed);

    // `mutations` steps; appends the expected-value deposits, each scaled by `scale`
    // (W H / M; the film applies b), to `out`.
    void run(int mutations, double scale, std::vector<FilmSplat>& out);

    long long accepted() const { return accepted_; }
    long long largeSteps() const { return largeSteps_; }
    long long largeAccepted() const { return largeAccepted_; }
    long long steps() const { return steps_; }
    // Sum of f over the large steps' proposals: uniform samples, independent of the chain, that
    // refine b.
    double largeStepSum() const { return largeStepSum_; }

private:
    const PinholeCamera& camera_;
    BdptTracer tracer_;
    PssSampler sampler_;
    PathContribution current_, proposed_;
    long long steps_ = 0, accepted_ = 0, largeSteps_ = 0, largeAccepted_ = 0;
    double largeStepSum_ = 0;
};

}  // namespace lucerna
