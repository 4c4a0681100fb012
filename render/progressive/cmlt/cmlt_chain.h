#pragma once
// The per-thread part of the cmlt backend: coherent Metropolis light transport (Segovia et al.
// 2007, "Coherent Metropolis Light Transport with Multiple-Try Mutations"), in primary sample
// space over the bidirectional sampler.
//
//   1. The MLT chain (mlt_chain.h) explores path space; each of its states is a seed, distributed
//      in proportion to its image contribution f.
//   2. Around each seed, a sub-chain of lens mutations: only the raster point moves, by a
//      Gaussian of sigmaPixels (wrapped around the image, so symmetric), every other number of
//      the state stays; the path behind the pixel follows (for E S* D ... paths this is the lens
//      perturbation). Each step draws `tries` candidates from the current state together; their
//      camera rays are neighbours and are traced as one coherent Embree packet.
//   3. Every candidate is accumulated with its expected value: candidate y_i with
//      a_i / f(y_i), its competitor (the current state x) with (1 - a_i) / f(x),
//      a_i = min(1, f(y_i) / f(x)). Each pair is one step's expected deposit from x, so the lens
//      step counts as `tries` steps of weight 1. The chain then moves to one candidate chosen
//      uniformly, accepted with its a_i: a Metropolis-Hastings step with a symmetric kernel, so
//      the sub-chain keeps the density f and the seeds' distribution.
// Every step deposits total weight 1, so the scheduler's W H / steps normalisation holds. The
// candidates share the current state's light subpath and its light-tracing splats (the light
// and connection streams do not move; the subpath is traced again only when the seed's own
// proposal was rejected) and their camera rays are one packet: a candidate costs a camera
// subpath and its connections. By measurement the defaults are single tries (BENCHMARKS.md):
// the saving is the light subpath, not the packet.
//
//   2'. With settings.causticSteps > 0, as many caustic steps after the lens steps
//      (caustic_mutation.h): the camera subpath of the current state is traced once, and each of
//      `tries` candidates moves only the light stream (a light subpath and the connections each),
//      deposited and chosen as in 3.

#include "render/progressive/cmlt/caustic_mutation.h"
#include "render/progressive/cmlt/cmlt_settings.h"
#include "render/progressive/cmlt/lens_mutation.h"
#include "render/progressive/mlt/mlt_chain.h"

namespace lucerna {

class CmltChain final : public MltChain {
public:
    CmltChain(const RenderScene& scene, const CmltSettings& settings, uint64_t bootstrapSeed);

    // Alternates one MLT step (a new seed) with settings.lensSteps lens steps and
    // settings.causticSteps caustic steps, until `steps`.
    int run(int steps, double scale, std::vector<FilmSplat>& out) override;

private:
    // One lens or caustic step; each returns the steps it counts for (tries: one per candidate).
    // lightSubpathCurrent: the tracer holds the current state's light subpath.
    int lensStep(double scale, bool lightSubpathCurrent, std::vector<FilmSplat>& out);
    int causticStep(double scale, std::vector<FilmSplat>& out);
    // Step 3 over candidates_: deposits every candidate and the competitor by their expected
    // values, then draws the move (which candidate, accepted or not).
    LensMove depositAndChoose(double scale, std::vector<FilmSplat>& out);

    const RenderScene& scene_;
    CmltSettings settings_;
    std::vector<V2f> rasters_;
    std::vector<Ray> rays_;
    std::vector<std::optional<SurfacePoint>> hits_;
    std::vector<PathContribution> candidates_;
    std::vector<double> candidateF_;
    CausticTries causticTries_;
};

}  // namespace lucerna
