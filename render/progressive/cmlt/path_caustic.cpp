#include "render/progressive/cmlt/path_caustic.h"

#include "render/progressive/cmlt/specular_chain.h"
#include "render/trace/ray_offset.h"

#include <cmath>
#include <numbers>

namespace lucerna {

V3f perturbDirection(const V3f& w, float sigma, Rng& rng) {
    const double theta = sigma * std::sqrt(-2.0 * std::log(1.0 - rng.nextDouble()));
    const double phi = 2.0 * std::numbers::pi * rng.nextDouble();
    const double s = std::sin(theta);
    const Frame frame(w);
    return frame.toWorld(V3f(float(s * std::cos(phi)), float(s * std::sin(phi)), float(std::cos(theta)))).normalized();
}

bool CausticPath::build(const std::vector<PathVertex>& path) {
    const int k = int(path.size()) - 1;
    if (k < 3 || path[1].delta || path[0].kind != VertexKind::Camera) return false;
    for (int j = 2; j < k; ++j)
        if (!path[size_t(j)].delta) return false;
    light_ = path[size_t(k)];
    // Parallel light and the sky have no place to perturb a direction from.
    if (light_.kind == VertexKind::DirectionalLight || light_.atInfinity() || light_.kind == VertexKind::Camera) return false;
    if (light_.kind == VertexKind::Surface && !scene_.material(light_.sp.material).isEmitter()) return false;
    sensorPoint_ = int(path[0].light);
    refracted_.clear();
    for (int j = k - 1; j >= 2; --j) refracted_.push_back(refractedAt(path, j));
    direction_ = (path[size_t(k - 1)].p() - light_.p()).normalized();
    return true;
}

Rgb CausticPath::contribution(const V3f& w, float& rasterX, float& rasterY) const {
    const Rgb le = densities_.emitted(light_, w);
    if (isBlack(le)) return Rgb(0, 0, 0);
    const bool area = light_.onSurface();
    Ray ray{area ? light_.sp.spawnOrigin(w) : light_.p(), w};
    Rgb through;
    std::optional<SurfacePoint> hit = scene_.intersect(ray, nullptr, &through);
    Rgb throughput = le * through * (area ? std::abs(light_.sp.ng.dot(w)) : 1.0f);
    for (const bool refracted : refracted_) {
        if (!hit || !followSpecular(scene_, *hit, refracted, ray, throughput)) return Rgb(0, 0, 0);
        hit = scene_.intersect(ray, nullptr, &through);
        throughput *= through;
    }
    if (!hit) return Rgb(0, 0, 0);
    const ShadingMaterial& mat = scene_.material(hit->material);
    if (mat.isDelta() || mat.isEmitter()) return Rgb(0, 0, 0);

    const V3f sensor = scene_.camera().position(sensorPoint_);
    const V3f d = sensor - hit->p;
    const float dist2 = d.length2();
    if (!(dist2 > 0.0f)) return Rgb(0, 0, 0);
    PathVertex y1;
    y1.kind = VertexKind::Surface;
    y1.sp = *hit;
    y1.wo = d / std::sqrt(dist2);  // toward the sensor
    if (!scene_.camera().rasterPoint(sensorPoint_, -y1.wo, rasterX, rasterY)) return Rgb(0, 0, 0);
    const Rgb c = throughput * densities_.bsdf(y1, -ray.direction.normalized()) *
                  (std::abs(y1.sp.ng.dot(y1.wo)) * densities_.cameraImportance(sensorPoint_, -y1.wo) / dist2);
    if (isBlack(c) || !isFinite(c)) return Rgb(0, 0, 0);
    const V3f from = y1.sp.spawnOrigin(y1.wo);
    return c * scene_.transmittance(Ray{from, sensor - from, 0.0f, kShadowRayEnd});
}

}  // namespace lucerna
