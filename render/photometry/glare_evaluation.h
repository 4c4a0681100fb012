#pragma once
// UGR at an observer in a scene (CIE 117-1995; README, "Glare (UGR)"): the sum over the
// luminaires the eye sees of L^2 omega / p^2 (core/photometry/glare.h) against the background luminance Lb,
// the indirect illuminance at the eye over pi.
//
// What is evaluated: the scene without maintenance factors (UGR is rated for the new
// installation, CIE 117) and without the lights switched off; daylight (the sky, suns and
// directional lights) is left out, since UGR rates the electric lighting.
//   - Sources: luminaires whose centre lies in the field of view of core/photometry/glare.h, with their
//     luminance from their photometric data and luminous area (the "luminous_area" key, or the
//     file's opening), each seen along one ray from the eye to its centre: an opaque surface on
//     the way hides it (one within 1 cm of the luminaire, its own ceiling, does not), glazing
//     scales its luminance by its transmittance. Point and spot lights (no luminous area),
//     luminaires whose file states none, and emitter objects (area lights) are not rated: they
//     are named in the notes. Emitter objects' light, direct included, counts in the background.
//   - Background: the illuminance at the eye on a vertical plane facing the line of sight, by
//     computeGridIlluminance at that one point (the method of the settings), less the direct
//     light of every luminaire, point and spot light there (exact, one shadow ray each, as the
//     grid methods sum it): what is left is the indirect light CIE 117 asks for. Its 95% error
//     bar gives UGR's (8 log10 of the ratio).
// The line of sight is the view direction made horizontal (CIE 117 assumes a horizontal line of
// sight); a view straight up or down is refused (std::invalid_argument).

#include "core/scene/scene.h"
#include "core/task_system.h"
#include "render/photometry/grid_calculation.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct GlareSettings {
    GridMethod backgroundMethod = GridMethod::Path;   // how the illuminance at the eye is estimated
    double targetRelativeError = 0.03;                // of the background illuminance
    double timeLimitSeconds = 0;                      // 0: none
    uint64_t seed = 1;
    int samplesPerPass = 0;                           // 0: the method's default
};

struct LuminaireGlare {
    std::string light;          // the light's name
    double luminanceCdM2 = 0;   // L toward the eye
    double solidAngleSr = 0;    // omega
    double positionIndex = 0;   // p
    double share = 0;           // its L^2 omega / p^2 over the sum
};

struct GlareResult {
    std::optional<double> ugr;          // absent: no luminaire in the field of view
    double backgroundLuminanceCdM2 = 0; // Lb
    double ugrErrorBar = 0;             // from the background's 95% error bar
    std::vector<LuminaireGlare> sources;// in the field of view, largest share first
    std::vector<std::string> notes;     // lights left out and why (a point light: no luminous area; hidden; ...)
};

// `scene` as loaded (meshes and luminaire files resolved). Cancelled through ctx, it returns what
// the last finished pass gave.
GlareResult evaluateGlare(const Scene& scene, const GlareObserver& observer, const GlareSettings& settings,
                          TaskContext& ctx);

// Observers that share one view direction (a UGR grid): one background calculation for all.
struct GlareGridResult {
    std::vector<GlareResult> observers;  // in the order of the positions
    int passes = 0;
    double seconds = 0;
    bool converged = false;              // every background within the target
    GridMethod method = GridMethod::Path;
};
// `onPass`, if given, sees the result after each pass of the background (on the calling thread).
GlareGridResult evaluateGlareGrid(const Scene& scene, const std::vector<V3d>& positions, const V3d& view,
                                  const GlareSettings& settings, TaskContext& ctx,
                                  const std::function<void(const GlareGridResult&)>& onPass = {});

}  // namespace lucerna
