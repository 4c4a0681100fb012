#pragma once
// Settings of the coherent Metropolis light transport backend.

#include "render/progressive/mlt/mlt_settings.h"

namespace lucerna {

struct CmltSettings {
    MltSettings mlt;          // step 1: the chain that explores path space and yields seeds
    // Defaults: the best of a sweep on the Cornell box at equal time (BENCHMARKS.md, issue 4);
    // longer sub-chains and more tries concentrate correlated deposits around each seed.
    int lensSteps = 1;        // step 2: lens sub-chain steps around each seed
    int tries = 4;            // candidates per lens step, traced together as a packet
    float sigmaPixels = 4.0f; // the lens perturbation's Gaussian, in pixels
    // Caustic sub-chain steps around each seed (caustic_mutation.h), after the lens steps: the
    // light stream moves, the camera subpath is traced once for all `tries` candidates.
    int causticSteps = 0;

    // Reads "lens_steps", "tries", "sigma_pixels", "caustic_steps" and mlt's own options; throws
    // std::invalid_argument on bad values.
    static CmltSettings fromOptions(const RenderSettings& settings);
};

}  // namespace lucerna
