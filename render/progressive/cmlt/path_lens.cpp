#include "render/progressive/cmlt/path_lens.h"

#include "render/progressive/cmlt/specular_chain.h"
#include "render/trace/ray_offset.h"

namespace lucerna {

namespace {
V3f toward(const PathVertex& from, const PathVertex& to) { return (to.p() - from.p()).normalized(); }
}  // namespace

bool LensPath::build(const std::vector<PathVertex>& path) {
    const int k = int(path.size()) - 1;
    if (k < 1) return false;
    m_ = 1;
    while (m_ < k && path[size_t(m_)].delta) ++m_;
    if (path[size_t(m_)].delta) return false;
    refracted_.assign(size_t(m_), false);
    for (int j = 1; j < m_; ++j) refracted_[size_t(j)] = refractedAt(path, j);
    endsAtM_ = m_ == k;
    rest_ = Rgb(1, 1, 1);
    keepsDirection_ = false;
    if (endsAtM_) return true;
    if (path[size_t(m_ + 1)].delta) return buildKeepingDirection(path);

    next_ = path[size_t(m_ + 1)];
    nextIsLast_ = m_ + 1 == k;
    if (next_.kind == VertexKind::DirectionalLight || next_.kind == VertexKind::Camera) return false;
    if (next_.kind == VertexKind::Surface) {
        const ShadingMaterial& mat = scene_.material(next_.sp.material);
        if (mat.isDelta() || mat.isEmitter() != nextIsLast_) return false;
        if (!nextIsLast_) next_.wo = toward(next_, path[size_t(m_ + 2)]);
    }
    // R: the vertices after x_{m+1}, and the light's colour.
    for (int j = m_ + 2; j < k; ++j) {
        PathVertex v = path[size_t(j)];
        const ShadingMaterial& mat = scene_.material(v.sp.material);
        if (mat.isDelta()) {
            if (mat.type == MaterialType::Mirror) rest_ *= mat.reflectance;
            continue;
        }
        v.wo = toward(v, path[size_t(j - 1)]);
        rest_ *= densities_.bsdf(v, toward(v, path[size_t(j + 1)]));
        rest_ /= std::max(maxComponent(rest_), 1e-30f);  // its scale is free: kept near 1 on long paths
    }
    if (!nextIsLast_) {
        const PathVertex& light = path[size_t(k)];
        if (light.kind == VertexKind::DirectionalLight) {
            const LightSampler& lights = scene_.lights();
            rest_ *= lights.deltaLights()[light.light - lights.emitters().size()].intensity;
        } else {
            rest_ *= densities_.emitted(light, toward(light, path[size_t(k - 1)]));
        }
        rest_ /= std::max(maxComponent(rest_), 1e-30f);
    }
    return !isBlack(rest_) && isFinite(rest_);
}

bool LensPath::buildKeepingDirection(const std::vector<PathVertex>& path) {
    const int k = int(path.size()) - 1;
    if (m_ < 2) return false;  // (E D S+ L: the caustic perturbation's, path_caustic.h)
    const PathVertex& light = path[size_t(k)];
    if (!light.onSurface()) return false;
    lightSideRefracted_.clear();
    for (int j = m_ + 1; j < k; ++j) {
        if (!path[size_t(j)].delta) return false;
        lightSideRefracted_.push_back(refractedAt(path, j));
    }
    direction_ = toward(path[size_t(m_)], path[size_t(m_ + 1)]);
    keepsDirection_ = true;
    return true;
}

Rgb LensPath::contribution(float x, float y, const std::optional<SurfacePoint>& primaryHit) const {
    Ray ray = scene_.camera().ray(x, y);
    const SurfacePoint* hit = primaryHit ? &*primaryHit : nullptr;
    std::optional<SurfacePoint> traced;
    Rgb throughput(1, 1, 1);  // P
    for (int j = 1; j < m_; ++j) {
        if (!hit || !followSpecular(scene_, *hit, refracted_[size_t(j)], ray, throughput)) return Rgb(0, 0, 0);
        traced = scene_.intersect(ray);
        hit = traced ? &*traced : nullptr;
    }
    if (!hit) return Rgb(0, 0, 0);
    PathVertex ym;
    ym.kind = VertexKind::Surface;
    ym.sp = *hit;
    ym.wo = -ray.direction.normalized();
    const ShadingMaterial& mat = scene_.material(hit->material);
    if (endsAtM_) return mat.isEmitter() ? throughput * densities_.emitted(ym, ym.wo) : Rgb(0, 0, 0);
    if (mat.isDelta() || mat.isEmitter()) return Rgb(0, 0, 0);
    if (keepsDirection_) return throughput * alongDirection(ym);

    const V3f d = next_.p() - ym.p();
    const float dist2 = d.length2();
    if (!(dist2 > 0.0f)) return Rgb(0, 0, 0);
    const V3f w = d / std::sqrt(dist2);  // y_m toward x_{m+1}
    const float g = std::abs(ym.sp.ng.dot(w)) * (next_.onSurface() ? std::abs(next_.sp.ng.dot(w)) : 1.0f) / dist2;
    const Rgb atNext = nextIsLast_ ? densities_.emitted(next_, -w) : densities_.bsdf(next_, -w);
    const Rgb c = throughput * densities_.bsdf(ym, w) * atNext * rest_ * g;
    if (isBlack(c) || !isFinite(c)) return Rgb(0, 0, 0);
    if (next_.onSurface()) return scene_.unoccluded(ym.sp, next_.sp) ? c : Rgb(0, 0, 0);
    const V3f from = ym.sp.spawnOrigin(w);
    return scene_.occluded(Ray{from, next_.p() - from, 0.0f, kShadowRayEnd}) ? Rgb(0, 0, 0) : c;
}

Rgb LensPath::alongDirection(const PathVertex& ym) const {
    Rgb c = densities_.bsdf(ym, direction_) * std::abs(ym.sp.ng.dot(direction_));
    if (isBlack(c)) return c;
    Ray ray{ym.sp.spawnOrigin(direction_), direction_};
    std::optional<SurfacePoint> hit = scene_.intersect(ray);
    for (const bool refracted : lightSideRefracted_) {
        if (!hit || !followSpecular(scene_, *hit, refracted, ray, c)) return Rgb(0, 0, 0);
        hit = scene_.intersect(ray);
    }
    if (!hit) return Rgb(0, 0, 0);
    PathVertex emitter;
    emitter.kind = VertexKind::Surface;
    emitter.sp = *hit;
    c *= densities_.emitted(emitter, -ray.direction.normalized());
    return isFinite(c) ? c : Rgb(0, 0, 0);
}

}  // namespace lucerna
