#pragma once
// Settings of the Metropolis light transport backend.

#include "render/progressive/bdpt/bdpt_settings.h"

namespace lucerna {

struct MltSettings {
    BdptSettings bdpt;               // the bidirectional sampler the chains drive
    int bootstrapSamples = 65536;    // uniform samples per film half: b = int f, and the chains' seeds
    // Where over 0: the bootstrap samples per pixel drawn before the first pass (at least 4096),
    // the chains' seeds among them; the rest at the half's second pass or when asked
    // (completePreparation), the chains then seeded again among all. So a method that is tried
    // for a pass (auto's pilots) does not pay the whole bootstrap. 0.25 where
    // RenderSettings::deferPreparation, else 0.
    float firstBootstrapPerPixel = 0.0f;
    int chains = 128;                // independent chains per film half
    float mutationsPerPixel = 1.0f;  // mutations per pass, per pixel of the image
    float largeStepProbability = 0.3f;
    float sigma = 0.01f;             // small steps: standard deviation in primary sample space
    // Of the small steps, the share that moves the light stream alone (the caustic perturbation
    // in primary sample space; pss_sampler.h).
    float causticProbability = 0.0f;

    // Reads "bootstrap", "bootstrap_first_per_pixel", "chains", "mutations", "large_step",
    // "sigma", "caustic" and bdpt's own options over `defaults`; throws std::invalid_argument on
    // bad values.
    static MltSettings fromOptions(const RenderSettings& settings, MltSettings defaults);
    static MltSettings fromOptions(const RenderSettings& settings) { return fromOptions(settings, MltSettings()); }
};

}  // namespace lucerna
