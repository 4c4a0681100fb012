#include "render/engine/measured_auto/measured_auto_settings.h"

#include <algorithm>

namespace lucerna {

std::vector<std::string> autoCandidates(const Scene& scene) { return autoCandidates(analyseFeatures(scene)); }

std::vector<std::string> autoCandidates(const SceneFeatures& f) {
    // Not mlt: cmlt is mlt with coherent mutations added, and where it lost to mlt it lost by
    // little (the caustic slab mirror: 1.02 of mlt's relmse), while mlt's short runs flattered
    // it: on the two-mirror caustic (seed 9) its pilot led, it took 90% of the time and the image
    // came out 2.4 times cmlt's alone; on the small-light caustic mlt alone was 3.1 times cmlt's
    // mean error over 8 seeds, and it had carried a firefly into auto's image there. Its pilot
    // also cost 5% of a 10 s render (BENCHMARKS.md, R105).
    if (!f.hasSpecular()) return {"path", "bdpt", "ir", "mir", "cmlt"};
    // A path tracer finds a caustic only by hitting its emitter after the specular bounces, so it
    // is consistent where every light has an area (emitters, the sky), not a point or a single
    // direction (point, spot, luminaire, directional, the sun). Last, so that the others keep
    // their replicas' seeds (their index) with or without it.
    if (!f.hasDeltaLights() && !f.hasSun) return {"bdpt", "cmlt", "path"};
    return {"bdpt", "cmlt"};
}

MeasuredAutoSettings MeasuredAutoSettings::forScene(const Scene& scene, const RenderSettings& render) {
    MeasuredAutoSettings s;
    const SceneFeatures features = analyseFeatures(scene);
    s.candidates = autoCandidates(features);
    s.caustics = features.hasSpecular();
    s.cost = render.spp > 0 ? AutoCost::Rays : AutoCost::Seconds;
    // A hundredth of the budget each, so that the pilots of five methods take a twentieth of it
    // at most (and a method far behind stops after its first pass); half a second where the
    // render is open-ended (the window).
    if (render.seconds > 0) s.pilotSeconds = std::clamp(0.01 * render.seconds, 0.1, 2.0);
    if (s.cost == AutoCost::Seconds) s.budgetSeconds = std::max(0.0, render.seconds);
    return s;
}

}  // namespace lucerna
