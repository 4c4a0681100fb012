#pragma once
// The settings of `--backend auto` (measured_auto_backend.h): which methods it measures, how long
// their pilots run, and how often it measures again.

#include "core/scene/scene.h"
#include "render/backend/backend.h"

#include <string>
#include <vector>

namespace lucerna {

// What auto counts as a method's cost: seconds of its passes, or, where the render is counted
// in passes (--spp), the rays its passes trace, so that a render with a seed is reproducible.
enum class AutoCost { Seconds, Rays };

struct MeasuredAutoSettings {
    // The methods that are consistent for the scene, in the order their pilots run.
    std::vector<std::string> candidates;
    bool caustics = false;  // the scene has mirrors or glass (trial.h, shortRunIsFair)
    AutoCost cost = AutoCost::Seconds;
    int tileSize = 16;         // pixels per side of the squares the measures pool over
    int pilotPasses = 1;       // passes of each replica before a method is measured
    // Seconds of each method's pilot (AutoCost::Seconds), unless its gain falls below
    // dropBelow of the best's first (a method far behind costs no more than its first passes).
    double pilotSeconds = 0.5;
    double dropBelow = 0.1;
    // The render's budget in seconds (AutoCost::Seconds with a time limit); 0 where it is
    // open-ended (the window) or counted in passes.
    double budgetSeconds = 0;
    // The measures are taken again when the render's cost has grown by this share (each costs
    // the images of every replica).
    double remeasureGrowth = 0.25;

    static MeasuredAutoSettings forScene(const Scene& scene, const RenderSettings& render);
};

// The methods auto may combine for `scene`. Every one must be consistent, so that the combination
// is: with mirrors or glass, the ones with light-side strategies (bdpt, cmlt; VPLs cannot carry a
// caustic), and path where no light is a point or a single direction (a path tracer cannot find a
// point light's caustic); otherwise path, bdpt, ir, mir and cmlt. Never mlt, which cmlt extends
// (measured_auto_settings.cpp).
std::vector<std::string> autoCandidates(const Scene& scene);
std::vector<std::string> autoCandidates(const SceneFeatures& features);

}  // namespace lucerna
