#include "render/progressive/cmlt/path_lens.h"

#include "render/trace/ray_offset.h"

namespace lucerna {

namespace {
V3f toward(const PathVertex& from, const PathVertex& to) { return (to.p() - from.p()).normalized(); }

// A specular vertex's factor in path space: the mirror's reflectance, glass's Fresnel
// reflectance or transmittance (the sampled weight is 1 because the branch is chosen by them).
Rgb specularFactor(const ShadingMaterial& mat, const V3f& woLocal, bool refracted) {
    if (mat.type == MaterialType::Mirror) return mat.reflectance;
    const bool outside = woLocal.z >= 0.0f;
    const float fr = fresnelDielectric(std::abs(woLocal.z), outside ? mat.ior : 1.0f / mat.ior);
    return Rgb(refracted ? 1.0f - fr : fr);
}
}  // namespace

bool LensPath::build(const std::vector<PathVertex>& path) {
    const int k = int(path.size()) - 1;
    if (k < 1) return false;
    m_ = 1;
    while (m_ < k && path[size_t(m_)].delta) ++m_;
    if (path[size_t(m_)].delta) return false;
    refracted_.assign(size_t(m_), false);
    for (int j = 1; j < m_; ++j) {
        const PathVertex& v = path[size_t(j)];
        const float a = v.sp.ng.dot(toward(v, path[size_t(j - 1)])), b = v.sp.ng.dot(toward(v, path[size_t(j + 1)]));
        refracted_[size_t(j)] = a * b < 0.0f;
    }
    endsAtM_ = m_ == k;
    rest_ = Rgb(1, 1, 1);
    if (endsAtM_) return true;

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

Rgb LensPath::contribution(float x, float y, const std::optional<SurfacePoint>& primaryHit) const {
    Ray ray = scene_.camera().ray(x, y);
    const SurfacePoint* hit = primaryHit ? &*primaryHit : nullptr;
    std::optional<SurfacePoint> traced;
    Rgb throughput(1, 1, 1);  // P
    for (int j = 1; j < m_; ++j) {
        if (!hit) return Rgb(0, 0, 0);
        const ShadingMaterial& mat = scene_.material(hit->material);
        if (!mat.isDelta()) return Rgb(0, 0, 0);
        const V3f wo = -ray.direction.normalized();
        const Frame frame(shadingNormalToward(mat, hit->ng, wo));
        const V3f woLocal = frame.toLocal(wo);
        BsdfSample bs;
        // The recorded branch, forced: uLobe 0 reflects whenever glass can, 1 refracts whenever it can.
        if (!bsdfSample(mat, woLocal, V2f(0, 0), refracted_[size_t(j)] ? 1.0f : 0.0f, bs) ||
            bs.refracted != refracted_[size_t(j)])
            return Rgb(0, 0, 0);
        throughput *= specularFactor(mat, woLocal, bs.refracted);
        const V3f wi = frame.toWorld(bs.wi);
        ray = Ray{hit->spawnOrigin(wi), wi};
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

}  // namespace lucerna
