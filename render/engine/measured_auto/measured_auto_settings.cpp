#include "render/engine/measured_auto/measured_auto_settings.h"

#include <algorithm>

namespace lucerna {

std::vector<std::string> autoCandidates(const Scene& scene) {
    const SceneFeatures f = analyseFeatures(scene);
    if (!f.hasSpecular()) return {"path", "bdpt", "ir", "mir", "mlt", "cmlt"};
    // A path tracer finds a caustic only by hitting its emitter after the specular bounces, so it
    // is consistent where every light has an area (emitters, the sky), not a point or a single
    // direction (point, spot, luminaire, directional, the sun). Last, so that the others keep
    // their replicas' seeds (their index) with or without it.
    if (!f.hasDeltaLights() && !f.hasSun) return {"bdpt", "mlt", "cmlt", "path"};
    return {"bdpt", "mlt", "cmlt"};
}

MeasuredAutoSettings MeasuredAutoSettings::forScene(const Scene& scene, const RenderSettings& render) {
    MeasuredAutoSettings s;
    s.candidates = autoCandidates(scene);
    s.cost = render.spp > 0 ? AutoCost::Rays : AutoCost::Seconds;
    // A hundredth of the budget each, so that the pilots of six methods take a sixteenth of it
    // at most (and a method far behind stops after its first pass); half a second where the
    // render is open-ended (the window).
    if (render.seconds > 0) s.pilotSeconds = std::clamp(0.01 * render.seconds, 0.1, 2.0);
    if (s.cost == AutoCost::Seconds) s.budgetSeconds = std::max(0.0, render.seconds);
    return s;
}

}  // namespace lucerna
