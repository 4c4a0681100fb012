#pragma once
// Settings of the coherent Metropolis light transport backend.

#include "render/progressive/mlt/mlt_settings.h"

namespace lucerna {

struct CmltSettings {
    // Step 1: the chain that explores path space and yields seeds. Half its steps are large
    // (mlt's own: 0.3): the sub-chains explore around each seed, so the chain's work is to go
    // everywhere and to leave a path that is a spike soon; a chain stuck there carries its
    // sub-chains with it (docs/benchmarks-history.md, issue 4, "Session 10").
    MltSettings mlt = [] {
        MltSettings m;
        m.largeStepProbability = 0.5f;
        return m;
    }();
    // Defaults by measurement at equal time (docs/benchmarks-history.md, issue 4, "Session 8" and
    // "Session 9", the chain then at 0.3 large steps): 8 path-space lens steps a seed reach mlt's
    // expected error 1.46 times sooner on the caustic scene (24 runs; 16 steps: 0.9, 4: 1.41;
    // with fewer steps the chain mutates more often, so a chain stuck on a path no perturbation
    // leaves weighs less), 6.5 times on the door scene (16: 7.7) and 1.7 on the Cornell box (16:
    // 1.8); four tries a step, or primary-sample-space lens steps besides, did no better.
    int pathLensSteps = 8;    // step 2: path-space lens sub-chain steps around each seed (path_lens.h)
    int tries = 1;            // candidates a step (all lens kinds), their camera rays one packet
    float sigmaPixels = 4.0f; // the lens perturbations' Gaussian, in pixels
    float causticSigma = 0.01f;  // the path-space caustic perturbation's turn (Rayleigh scale), radians
    // Primary-sample-space lens steps on the chain before the path-space sub-chain (the whole
    // sample traced again at the moved raster point, the light subpath and its splats reused).
    // Off: with the path-space steps they no longer paid (session 6 default: 2).
    int lensSteps = 0;
    // Caustic steps on the chain after the lens steps (caustic_mutation.h): the light stream
    // moves, the camera subpath is traced once for all `tries` candidates. Off: it made the door
    // and caustic scenes 1.7 to 2.3 times worse at equal time.
    int causticSteps = 0;

    // Reads "path_lens_steps", "tries", "sigma_pixels", "caustic_sigma", "lens_steps",
    // "caustic_steps" and mlt's own options; throws std::invalid_argument on bad values.
    static CmltSettings fromOptions(const RenderSettings& settings);
};

}  // namespace lucerna
