#pragma once
// Settings of the coherent Metropolis light transport backend.

#include "render/progressive/mlt/mlt_settings.h"

namespace lucerna {

struct CmltSettings {
    MltSettings mlt;          // step 1: the chain that explores path space and yields seeds
    // Defaults by measurement at equal time (BENCHMARKS.md, issue 4, session 6): on the door
    // scene two single-try lens steps reach mlt's error about 2x sooner, four tries of one step
    // 1.3x: the candidates of one step are strongly correlated, and on a CPU a packet of a few
    // camera rays saves little, while every lens step reuses the light subpath.
    int lensSteps = 2;        // step 2: lens sub-chain steps around each seed
    int tries = 1;            // candidates per lens or caustic step, their camera rays one packet
    float sigmaPixels = 4.0f; // the lens perturbation's Gaussian, in pixels
    // Caustic sub-chain steps around each seed (caustic_mutation.h), after the lens steps: the
    // light stream moves, the camera subpath is traced once for all `tries` candidates. Off:
    // it made the door and caustic scenes 1.7 to 2.3 times worse at equal time.
    int causticSteps = 0;

    // Reads "lens_steps", "tries", "sigma_pixels", "caustic_steps" and mlt's own options; throws
    // std::invalid_argument on bad values.
    static CmltSettings fromOptions(const RenderSettings& settings);
};

}  // namespace lucerna
