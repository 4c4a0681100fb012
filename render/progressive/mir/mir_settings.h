#pragma once
// Settings of the Metropolis instant radiosity backend.

#include "render/backend/backend_options.h"
#include "render/progressive/ir/ir_settings.h"
#include "render/vpl/metropolis.h"

namespace lucerna {

struct MirSettings {
    GatherSettings gather;
    VplOptions vpl;                // light sub-paths of the chain's paths
    int pathVplsPerPass = 64;      // n: chain steps, hence path VPLs, per pass
    int tries = 1;                 // multiple-try Metropolis trials per step (1: plain MH); MH beat
                                   // 4-try MTM at equal time on the door and Cornell scenes (BENCHMARKS.md)
    float largeStepProbability = 0.3f;
    int startCandidates = 1024;    // uniform candidates the chain starts from (importance resampling)
    int pcSamplesPerPass = 256;    // extra independent uniform path samples refining Pc each pass
    int importancePoints = 64;     // |S|: camera points a light path's importance is measured on
    float defensive = 0.2f;        // the target's floor, as a fraction of a VPL's mean importance
    int pilotPaths = 256;          // uniform light paths that set the floor

    // Reads "vpl_paths", "tries", "large_step", "pc_samples", "importance_points",
    // "defensive", "max_bounces",
    // "clamp", "compensate"; throws std::invalid_argument on bad values.
    static MirSettings fromOptions(const RenderSettings& settings);
};

inline MirSettings MirSettings::fromOptions(const RenderSettings& settings) {
    MirSettings s;
    s.gather = gatherSettingsFromOptions(settings);
    readOption(settings, "vpl_paths", s.pathVplsPerPass, 1);
    readOption(settings, "tries", s.tries, 1);
    readOption(settings, "large_step", s.largeStepProbability, 1e-3, 1.0);
    readOption(settings, "pc_samples", s.pcSamplesPerPass, 0);
    readOption(settings, "importance_points", s.importancePoints, 1);
    readOption(settings, "defensive", s.defensive, 1e-4, 1e4);
    readOption(settings, "max_bounces", s.vpl.maxBounces, 1);
    return s;
}

}  // namespace lucerna
