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

#include <map>
#include <string>
#include <vector>

namespace lucerna {

// What one point of primary sample space brings to the film.
struct PathContribution {
    std::vector<FilmSplat> deposits;  // the camera sample at its pixel and the light splats
    double f = 0;                     // sum of their luminances: the chain's target
    bool recordPaths = false;         // whether evaluating it fills `paths`
    SampledPaths paths;               // the paths behind the deposits (BdptTracer::recordPaths)
};

// Evaluates the BDPT sample that `sampler`'s current iteration maps to.
void evaluatePath(BdptTracer& tracer, const Sensor& camera, PssSampler& sampler, PathContribution& out);
// The same with the raster point (x, y) (pixels) and its camera ray's closest hit given: the
// sampler's first two numbers, which would have chosen the raster point, are read and ignored;
// with reuseLightSubpath, the tracer's previous light subpath (and its light-tracing splats)
// stands for the light stream's.
void evaluatePathAt(BdptTracer& tracer, float x, float y, const std::optional<SurfacePoint>& primaryHit,
                    bool reuseLightSubpath, PssSampler& sampler, PathContribution& out);

// The same with the tracer's camera subpath through (x, y) (BdptTracer::traceCameraSubpathOnly,
// from the same camera numbers) and a light subpath from the sampler's light stream.
void evaluateLightSideAt(BdptTracer& tracer, float x, float y, PssSampler& sampler, PathContribution& out);
// The raster point (pixels) that a state's first two numbers u choose.
V2f rasterPoint(const Sensor& camera, const V2f& u);

// Appends c's deposits times `weight` to `out` (nothing when weight is 0 or not finite); the
// product is taken in double, so a weight beyond a float's range (1 / a tiny f) still deposits.
void depositContribution(const PathContribution& c, double weight, std::vector<FilmSplat>& out);

// Counts of a chain's steps, summed over chains for the render's diagnostics.
struct ChainCounters {
    long long steps = 0, accepted = 0;            // every step that deposits (weight 1 each)
    long long largeSteps = 0, largeAccepted = 0;  // of those, Kelemen's large steps
    long long causticSteps = 0, causticAccepted = 0;  // light-stream-only small steps
    long long variantSteps = 0, variantAccepted = 0;  // the steps of a variant's own kernels
    double largeStepSum = 0;                      // f over the large steps' (uniform) proposals
    ChainCounters& operator+=(const ChainCounters& o);
};

class MltChain {
public:
    // A chain whose first state is the bootstrap sample drawn with seed `bootstrapSeed` (the
    // sampler's first large step replays it exactly). With recordPaths, every state keeps the
    // paths behind it (current().paths).
    MltChain(const RenderScene& scene, const MltSettings& settings, uint64_t bootstrapSeed, bool recordPaths = false);
    virtual ~MltChain() = default;

    // At least `steps` steps, each depositing its expected value (total weight 1) scaled by
    // `scale` (W H / M; the film applies b), into `out`; returns the steps made. Variants
    // (cmlt) interleave their own kernels, which leave the same density invariant.
    virtual int run(int steps, double scale, std::vector<FilmSplat>& out);
    // One step.
    void mutate(double scale, std::vector<FilmSplat>& out);

    // The chain's state, for kernels that extend it (cmlt's lens sub-chains): after changing the
    // sampler's state they must set current() to its contribution.
    PssSampler& sampler() { return sampler_; }
    BdptTracer& tracer() { return tracer_; }
    PathContribution& current() { return current_; }

    const ChainCounters& counters() const { return counters_; }
    // A variant's own counts (cmlt: its sub-chains' steps and acceptances) by name, to be summed
    // over chains; they are in counters().variantSteps and variantAccepted too.
    virtual std::map<std::string, long long> variantCounts() const { return {}; }

protected:
    const Sensor& camera_;
    ChainCounters counters_;

private:
    BdptTracer tracer_;
    PssSampler sampler_;
    float causticProbability_;
    PathContribution current_, proposed_;
};

}  // namespace lucerna
