#pragma once
// The per-thread part of the cmlt backend: coherent Metropolis light transport (Segovia et al.
// 2007, "Coherent Metropolis Light Transport with Multiple-Try Mutations"), with the primary
// sample space chain over the bidirectional sampler as its seed generator.
//
//   1. The MLT chain (mlt_chain.h) explores path space; each of its states is a seed, distributed
//      in proportion to its image contribution f.
//   2. Around each seed, a sub-chain of lens mutations in path space (path_lens.h): one path of
//      the seed's sample, chosen in proportion to its share of f, is perturbed by Veach's lens
//      perturbation: the raster point moves by a Gaussian of sigmaPixels (wrapped around the
//      image, so symmetric), the camera ray is traced through the same specular vertices to the
//      first diffuse one and joined to the rest of the path, which stays (or, where a mirror
//      or glass follows that vertex, sent on in the direction the path left it through the same
//      specular chain, to the light or to a diffuse vertex joined there: Veach's multi-chain
//      form). A candidate costs a camera ray, the specular chains and one shadow ray, against a
//      whole bidirectional sample for an MLT mutation. Each step draws `tries` candidates
//      together; their camera rays are neighbours and are traced as one coherent Embree packet.
//   3. Every candidate is accumulated with its expected value: candidate y_i with
//      a_i / F(y_i), its competitor (the current state x) with (1 - a_i) / F(x),
//      a_i = min(1, F(y_i) / F(x)). Each pair is one step's expected deposit from x, so a step
//      counts as `tries` steps of weight 1. The sub-chain then moves to one candidate chosen
//      uniformly, accepted with its a_i: a Metropolis-Hastings step with a symmetric kernel.
// The sub-chain leaves the MLT chain's state alone. Its start is distributed as F / b over paths
// (a path of a state u ~ f / b, chosen with probability f_i(u) / f(u), comes from strategy i
// with density w_i F / b, and the MIS weights w_i sum to 1), and its steps keep that density, so
// its deposits estimate the same image, normalised like the chain's own. A path that the lens
// perturbation cannot move (a caustic seen directly: a mirror or glass follows its first diffuse
// vertex and leads straight on to the light) is moved by Veach's caustic perturbation instead
// (path_caustic.h: the emission direction turns, the light ray crosses the same specular chain
// to a new diffuse vertex, which is joined to the sensor); any other path keeps its steps where
// it is, depositing them at once (the diagnostic mlt_path_unmoved: their share).
//
//   2'. With settings.lensSteps > 0, lens steps in primary sample space on the MLT chain itself
//      first: only the raster numbers move and the whole sample is traced again, sharing the
//      state's light subpath and its light-tracing splats (the light and connection streams do
//      not move); deposited and chosen as in 3 with f for F.
//   2''. With settings.causticSteps > 0, caustic steps on the chain (caustic_mutation.h): the
//      camera subpath of the current state is traced once, and each of `tries` candidates moves
//      only the light stream (a light subpath and the connections each), deposited and chosen
//      as in 3.
// Every step deposits total weight 1, so the scheduler's W H / steps normalisation holds.

#include "render/progressive/cmlt/caustic_mutation.h"
#include "render/progressive/cmlt/cmlt_settings.h"
#include "render/progressive/cmlt/lens_mutation.h"
#include "render/progressive/cmlt/path_caustic.h"
#include "render/progressive/cmlt/path_lens.h"
#include "render/progressive/mlt/mlt_chain.h"

namespace lucerna {

class CmltChain final : public MltChain {
public:
    CmltChain(const RenderScene& scene, const CmltSettings& settings, uint64_t bootstrapSeed);

    // Alternates one MLT step (a new seed) with settings.lensSteps lens steps,
    // settings.causticSteps caustic steps and a path-space lens sub-chain, until `steps`.
    int run(int steps, double scale, std::vector<FilmSplat>& out) override;
    // "lens_steps", "lens_accepted" (primary-sample-space lens steps), "path_lens_steps",
    // "path_lens_accepted", "path_caustic_steps", "path_caustic_accepted" (the path-space
    // sub-chains) and "path_still_steps" (steps on paths no perturbation moves).
    std::map<std::string, long long> variantCounts() const override;

private:
    // Steps of cmlt's own kernels, each also counted as a step (and acceptance) of the chain.
    struct Counters {
        long long lensSteps = 0, lensAccepted = 0;
        long long pathLensSteps = 0, pathLensAccepted = 0;
        long long pathCausticSteps = 0, pathCausticAccepted = 0;
        long long pathStillSteps = 0;  // deposited at once
    };
    // Counts `steps` (and `accepted` of them) of one of cmlt's kernels, in its own counter and
    // the chain's.
    void countSteps(long long& kernelSteps, long long steps);
    void countAccepted(long long& kernelAccepted, long long accepted);

    // One lens or caustic step; each returns the steps it counts for (tries: one per candidate).
    // lightSubpathCurrent: the tracer holds the current state's light subpath.
    int lensStep(double scale, bool lightSubpathCurrent, std::vector<FilmSplat>& out);
    int causticStep(double scale, std::vector<FilmSplat>& out);
    // The path-space sub-chain (step 2) of settings.pathLensSteps steps of `tries` candidates;
    // returns the steps made. Its path (pathVertices_) is moved by the lens perturbation, else by
    // the caustic perturbation, else not at all; lensSubChain and causticSubChain return false,
    // having deposited nothing, when theirs cannot move it.
    int pathLensSubChain(double scale, std::vector<FilmSplat>& out);
    bool lensSubChain(const StrategyRecord& seed, int p, double scale, std::vector<FilmSplat>& out);
    // The sub-chain's move drawn by depositAndChoose: if accepted, the candidate becomes
    // lensState_ and the step counts as accepted, overall and in `acceptedOfKind`; returns
    // whether it moved (the caller then moves its own parameter: raster point or direction).
    bool takeSubChainMove(const LensMove& move, int p, long long& acceptedOfKind);
    bool causticSubChain(int p, double scale, std::vector<FilmSplat>& out);
    // Room for p candidates, recording their paths as the state does.
    void prepareCandidates(int p);
    // Step 2's proposals: p raster points around x (rasters_) and the closest hits of their
    // camera rays (hits_), traced as one packet; room for p candidates.
    void proposeRasters(const V2f& x, int p);
    // Step 3 over candidates_ against the current state `cur`: deposits every candidate and the
    // competitor by their expected values, then draws the move (which candidate, accepted or not).
    LensMove depositAndChoose(const PathContribution& cur, double scale, std::vector<FilmSplat>& out);

    const RenderScene& scene_;
    CmltSettings settings_;
    std::vector<V2f> rasters_;
    std::vector<Ray> rays_;
    std::vector<std::optional<SurfacePoint>> hits_;
    std::vector<PathContribution> candidates_;
    std::vector<double> candidateF_;
    CausticTries causticTries_;
    VertexDensities densities_;
    LensPath lensPath_;
    CausticPath causticPath_;
    std::vector<V3f> directions_;  // the caustic candidates' emission directions
    PathContribution lensState_;   // the path-space sub-chain's current path
    std::vector<PathVertex> pathVertices_;
    Counters cmltCounters_;
};

}  // namespace lucerna
