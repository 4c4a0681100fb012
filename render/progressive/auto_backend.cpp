// `--backend auto`: the backend a scene needs, from what is in it and from a small probe of what
// the camera sees. The rules follow what each method can and cannot do (BENCHMARKS.md has the
// measurements behind them):
//   - Mirrors or glass make caustics: paths whose light side must be sampled from the light. A
//     path tracer cannot render a delta light's caustic at all and finds an area light's only by
//     chance, VPLs (straight connections) none; bidirectional path tracing has the strategies for
//     them. On the bundled caustic scene bdpt reaches a third of mlt's error and a quarter of
//     path's at equal time. When the light also reaches what the camera sees mostly indirectly,
//     Metropolis light transport (over the same bidirectional sampler) stays on the rare paths.
//   - Diffuse and glossy scenes where most of what the camera sees is lit directly: the path
//     tracer with next-event estimation converges fastest.
//   - Diffuse scenes where most of what the camera sees is lit only indirectly (a room lit
//     through a door ajar): Metropolis instant radiosity puts its VPLs where the camera sees
//     them; with sharp glossy surfaces (which VPLs render badly) Metropolis light transport.

#include "render/progressive/backend.h"
#include "render/trace/render_scene.h"
#include "render/trace/rng.h"

#include <cstdio>

namespace lucerna {

namespace {

struct CameraProbe {
    double seen = 0;           // camera rays that hit a non-emitting, non-specular surface
    double directlyLit = 0;    // of those, the ones whose light sample is unoccluded
    int rays = 0;
};

// Camera rays on a coarse jittered grid; at each first diffuse/glossy hit one light sample
// (chosen by power) and a shadow ray. Surfaces seen through mirrors and glass are not probed.
CameraProbe probeCamera(const RenderScene& scene) {
    CameraProbe p;
    const PinholeCamera& camera = scene.camera();
    const int nx = 48, ny = 36;
    Rng rng(0x6175746f, 0);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            ++p.rays;
            const V2f u = rng.next2D();
            const float x = (float(i) + u.x) / nx * float(camera.width());
            const float y = (float(j) + u.y) / ny * float(camera.height());
            const auto hit = scene.intersect(camera.ray(x, y));
            if (!hit) continue;
            const ShadingMaterial& mat = scene.material(hit->material);
            if (mat.isEmitter()) continue;
            if (mat.isDelta()) continue;
            p.seen += 1;
            LightSample ls;
            const V2f ul = rng.next2D();
            if (scene.lights().sample(*hit, ul, rng.next1D(), ls) && !scene.occluded(ls.shadowRay)) p.directlyLit += 1;
        }
    return p;
}

bool hasSharpGlossy(const Scene& scene) {
    for (const Material& m : scene.materials)
        if (m.type == MaterialType::Glossy && m.roughness < 0.15) return true;
    return false;
}

std::string percent(double part, double whole) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f%%", whole > 0 ? 100.0 * part / whole : 0.0);
    return buf;
}

}  // namespace

AutoChoice chooseAutoBackend(const Scene& scene) {
    const SceneFeatures f = analyseFeatures(scene);
    const RenderScene render(std::make_shared<const Scene>(scene), 64, 48);
    if (render.lights().empty()) return {"path", "path: the scene has no light, the image is black whatever renders it"};
    const CameraProbe probe = probeCamera(render);
    const std::string lit = percent(probe.directlyLit, probe.seen) + " of the surfaces the camera sees are lit directly";

    const bool mostlyIndirect = probe.seen > 0 && probe.directlyLit < 0.25 * probe.seen;
    if (f.hasSpecular()) {
        if (mostlyIndirect)
            return {"mlt", "mlt: mirrors or glass make caustics, and light arrives mostly indirectly (" + lit +
                               "): Metropolis stays on the rare paths that carry it"};
        return {"bdpt", "bdpt: mirrors or glass make caustics, which need light-side strategies (" + lit + ")"};
    }
    if (mostlyIndirect) {
        if (hasSharpGlossy(scene))
            return {"mlt", "mlt: light arrives mostly indirectly (" + lit +
                               ") onto sharp glossy surfaces, which VPLs render badly"};
        return {"mir", "mir: light arrives mostly indirectly (" + lit +
                           "); Metropolis instant radiosity puts its VPLs where the camera sees them"};
    }
    return {"path", std::string("path: ") + (f.hasGlossy ? "diffuse and glossy" : "diffuse only") + ", " + lit +
                        "; path tracing with next-event estimation converges fastest"};
}

}  // namespace lucerna
