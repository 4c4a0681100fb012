#include "render/photometry/grid_diagnosis.h"

#include "render/photometry/grid_statistics.h"

#include <cmath>
#include <numbers>

namespace lucerna {

namespace {
// A fixed cosine-weighted spiral over the hemisphere of +z (Fibonacci in the disc, lifted): the
// same probes for every point, so that the answer does not depend on a seed.
std::vector<V3f> hemisphereProbes(int count) {
    std::vector<V3f> dirs;
    dirs.reserve(size_t(count));
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < count; ++k) {
        const double r = std::sqrt((k + 0.5) / count);
        const double phi = golden * k;
        dirs.emplace_back(float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::sqrt(std::max(0.0, 1 - r * r))));
    }
    return dirs;
}
}  // namespace

std::vector<uint8_t> pointsInsideGeometry(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal) {
    const IrradianceEstimator estimator(scene);
    const std::vector<IrradianceSensor> sensors = sensorsAt(points, normal);
    const std::vector<V3f> probes = hemisphereProbes(kInsideProbeRays);
    const Frame frame(toFloat(normal).normalized());
    std::vector<uint8_t> inside(points.size(), 0);
    for (size_t i = 0; i < sensors.size(); ++i) {
        // From the lifted sensor: a grid lying on the floor must not see the floor it lies on.
        const IrradianceSensor s = estimator.lifted(sensors[i]);
        int backFaces = 0;
        for (const V3f& local : probes) {
            const V3f d = frame.toWorld(local);
            const std::optional<SurfacePoint> hit = scene.intersect(Ray{s.position, d});
            if (hit && hit->ng.dot(d) > 0) ++backFaces;
        }
        inside[i] = 4 * backFaces > 3 * kInsideProbeRays ? 1 : 0;
    }
    return inside;
}

std::vector<uint8_t> pointsLitThroughGlass(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal) {
    std::vector<uint8_t> lit(points.size(), 0);
    const LightSampler& lights = scene.lights();
    if (lights.deltaLights().empty() || !scene.features().hasDielectric) return lit;
    const IrradianceEstimator estimator(scene);
    const V3f n = toFloat(normal).normalized();
    const std::vector<IrradianceSensor> sensors = sensorsAt(points, normal);
    for (size_t i = 0; i < sensors.size(); ++i) {
        SurfacePoint x;
        x.p = estimator.lifted(sensors[i]).position;
        x.pError = V3f(0, 0, 0);
        x.ng = n;
        x.triangle = 0xffffffffu;
        for (size_t l = 0; l < lights.deltaLights().size() && !lit[i]; ++l) {
            LightSample ls;
            if (!lights.sampleDeltaLight(l, x, ls) || ls.wi.dot(n) <= 0 || isBlack(ls.value)) continue;
            if (scene.occluded(ls.shadowRay) && thinPaneTransmittance(scene, ls.shadowRay) > 0) lit[i] = 1;
        }
    }
    return lit;
}

bool carriesLightThroughGlass(GridMethod method) {
    switch (method) {
    case GridMethod::Bdpt:
    case GridMethod::Mir:
    case GridMethod::Mlt:
    case GridMethod::Cmlt: return true;
    case GridMethod::Path:
    case GridMethod::Vpl:
    case GridMethod::Preview: return false;
    }
    return false;
}

}  // namespace lucerna
