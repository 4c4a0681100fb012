// `--backend auto`: the backend a scene needs, from what is in it and from a small probe of what
// the camera sees. The rules follow what each method can and cannot do, and the measurements in
// BENCHMARKS.md ("`auto`'s choices", "Progressive backends (issue 3)") and
// docs/benchmarks-history.md ("Issue 4"):
//   - Mirrors or glass make caustics: paths whose light side must be sampled from the light. A
//     path tracer cannot render a delta light's caustic at all and finds an area light's only by
//     chance, VPLs (straight connections) none; bidirectional path tracing has the strategies for
//     them (caustic scene, equal time: bdpt 2.2e-3 est. relmse, mlt 9.5e-3, path 9.0e-3).
//   - Light that reaches what the camera sees mostly indirectly (a room lit through a door ajar):
//     coherent Metropolis light transport, whose chains stay on the few paths that come through
//     (door scene, time to bdpt's 30 s error: cmlt 3.0 s; mlt about equal to bdpt; 60 s: bdpt
//     0.030 relmse, mir 0.054 at best, ir 0.064, path 0.097). On the caustic scene bdpt is
//     ahead (cmlt takes 1.4 times bdpt's time to the same expected error over four runs, single
//     runs 0.9 to 1.8 times; session 10), and bdpt has no chains to stick, so it stays the choice; on
//     the Cornell box the path tracer is 4 to 5 times ahead of cmlt (BENCHMARKS.md,
//     "`auto`'s choices").
//   - Otherwise (diffuse and glossy surfaces lit mostly directly): the path tracer with
//     next-event estimation converges fastest (Cornell box, 60 s: path 3.4e-4, bdpt 4.3e-4).

#include "render/engine/backend_table.h"
#include "render/trace/render_scene.h"
#include "render/trace/rng.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lucerna {

namespace {

struct CameraProbe {
    double seen = 0;           // camera rays that hit a non-emitting, non-specular surface
    double directlyLit = 0;    // of those, the ones whose light sample is unoccluded
};

// Camera rays on a coarse jittered grid; at each first diffuse/glossy hit one light sample
// (chosen by power) and a shadow ray. Surfaces seen through mirrors and glass are not probed.
CameraProbe probeCamera(const RenderScene& scene) {
    CameraProbe p;
    const Sensor& camera = scene.camera();
    const int nx = 48, ny = 36;
    Rng rng(0x6175746f, 0);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const V2f u = rng.next2D();
            const float x = (float(i) + u.x) / nx * float(camera.width());
            const float y = (float(j) + u.y) / ny * float(camera.height());
            const auto hit = scene.intersect(camera.ray(x, y));
            if (!hit) continue;
            const ShadingMaterial& mat = scene.material(hit->material);
            if (mat.isEmitter() || mat.isDelta()) continue;
            p.seen += 1;
            LightSample ls;
            const V2f ul = rng.next2D();
            if (scene.lights().sample(*hit, ul, rng.next1D(), ls) && !scene.occluded(ls.shadowRay)) p.directlyLit += 1;
        }
    return p;
}

std::string percent(double part, double whole) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f%%", whole > 0 ? 100.0 * part / whole : 0.0);
    return buf;
}

}  // namespace

AutoChoice chooseAutoBackend(const Scene& scene) {
    const SceneFeatures f = analyseFeatures(scene);
    // A small image of the scene's own view (its aspect kept): only the probe's rays are traced.
    const int width = 64, height = std::max(1, int(std::lround(64.0 * scene.camera.height / scene.camera.width)));
    const RenderScene render(sceneAsRendered(std::make_shared<const Scene>(scene)), width, height);
    if (render.lights().empty()) return {"path", "path: the scene has no light, the image is black whatever renders it"};
    const CameraProbe probe = probeCamera(render);
    const std::string lit = percent(probe.directlyLit, probe.seen) + " of the surfaces the camera sees are lit directly";

    const bool mostlyIndirect = probe.seen > 0 && probe.directlyLit < 0.25 * probe.seen;
    if (f.hasSpecular())
        return {"bdpt", "bdpt: mirrors or glass make caustics, which need light-side strategies (" + lit + ")"};
    if (mostlyIndirect)
        return {"cmlt", "cmlt: light arrives mostly indirectly (" + lit +
                            "); Metropolis chains stay on the few paths that come through"};
    return {"path", std::string("path: ") + (f.hasGlossy ? "diffuse and glossy" : "diffuse only") + ", " + lit +
                        "; path tracing with next-event estimation converges fastest"};
}

}  // namespace lucerna
