#pragma once
// Settings of the Metropolis instant radiosity backend.

#include "render/backend/backend_options.h"
#include "render/progressive/ir/ir_settings.h"
#include "render/vpl/mir_chain.h"

namespace lucerna {

struct MirSettings {
    GatherSettings gather;
    MirChainSettings chain;        // tries: MH beat 4-try MTM at equal time on the door and
                                   // Cornell scenes (docs/benchmarks-history.md,
                                   // issue 3, "Targets")
    int pathVplsPerPass = 64;      // n: chain steps, hence path VPLs, per pass
    // Cheap samples refining Pc each pass (chain.pcSamples); -1: balanced against the gather's
    // error after the first two passes (pc_balance.h), an eighth of the pixel count, at least
    // 256, before.
    int pcSamplesPerPass = -1;

    // Reads "vpl_paths", "tries", "large_step", "pc_samples", "importance_points", "defensive",
    // "max_bounces", "clamp", "compensate", "residual_vpls" (0.5 with daylight, else 0),
    // "direct_samples" (4); throws std::invalid_argument on bad values. `daylight`: the scene has
    // a sky or a sun.
    static MirSettings fromOptions(const RenderSettings& settings, bool daylight = false);
};

inline MirSettings MirSettings::fromOptions(const RenderSettings& settings, bool daylight) {
    MirSettings s;
    // Four direct-light samples per camera sample: a mir pass gathers tens of VPLs per pixel, so
    // three more next-event and BSDF samples cost little, and where surfaces are lit directly
    // their noise was much of what is left (relmse at equal time with 4 against 1: 0.84 on the
    // daylit office over 4 seeds; the film's estimate on 7 scenes kept out of the choice, 2 seeds
    // each, 0.87 geometric mean, but 1.28 and 1.38 on two doors lit through a gap; against the
    // reference a closed sphere, whose error is likely the chain's normalisation, 0.98;
    // BENCHMARKS.md, R93, R94). ir's passes are cheap, and there 4 samples lost on most scenes: 1.
    GatherSettings defaults;
    defaults.directSamples = 4;
    // With daylight, half the clamp's residual from the VPLs at x2 and half from a path
    // (gather_settings.h): a path from x2 must find the light that came in through a window,
    // path tracing's noise, which mir is 5 times below on the daylit office. There relmse at
    // 30 s fell to 0.86 over 10 seeds (VPLs alone lost on room (e)); in rooms lit from inside,
    // where a path finds the lamps by next-event estimation, the share lost (1.1 to 1.4 on the
    // Cornell box, the office floor and two closed rooms). BENCHMARKS.md, R109.
    defaults.residualVplShare = daylight ? 0.5f : 0.0f;
    s.gather = gatherSettingsFromOptions(settings, defaults);
    s.chain.maxSpecularDepth = s.gather.maxSpecularDepth;
    readOption(settings, "vpl_paths", s.pathVplsPerPass, 1);
    readOption(settings, "tries", s.chain.tries, 1);
    readOption(settings, "large_step", s.chain.largeStepProbability, 1e-3, 1.0);
    readOption(settings, "pc_samples", s.pcSamplesPerPass, 0);
    readOption(settings, "importance_points", s.chain.importancePoints, 1);
    readOption(settings, "defensive", s.chain.defensive, 1e-4, 1e4);
    readOption(settings, "max_bounces", s.chain.vpl.maxBounces, 1);
    return s;
}

}  // namespace lucerna
