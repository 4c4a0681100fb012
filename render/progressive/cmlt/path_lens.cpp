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
    endsAtSky_ = path[size_t(k)].atInfinity();
    kept_.clear();
    keptEndsAtEmitter_ = false;
    rest_ = Rgb(1, 1, 1);
    if (endsAtM_) return true;
    // The multi-chain form: a direction kept wherever a mirror or glass follows a diffuse vertex.
    int n = m_;
    while (path[size_t(n + 1)].delta) {
        KeptDirection d;
        d.w = toward(path[size_t(n)], path[size_t(n + 1)]);
        for (n = n + 1; n < k && path[size_t(n)].delta; ++n) d.refracted.push_back(refractedAt(path, n));
        kept_.push_back(std::move(d));
        if (n == k) {
            keptEndsAtEmitter_ = true;
            const bool causticSeenDirectly = m_ == 1 && kept_.size() == 1;  // path_caustic.h's
            return (path[size_t(k)].onSurface() || endsAtSky_) && !causticSeenDirectly;
        }
    }
    return buildJoin(path, n);
}

bool LensPath::buildJoin(const std::vector<PathVertex>& path, int n) {
    const int k = int(path.size()) - 1;
    next_ = path[size_t(n + 1)];
    nextIsLast_ = n + 1 == k;
    if (next_.kind == VertexKind::DirectionalLight || next_.kind == VertexKind::Camera) return false;
    if (next_.kind == VertexKind::Surface) {
        const ShadingMaterial& mat = scene_.material(next_.sp.material);
        if (mat.isDelta() || mat.isEmitter() != nextIsLast_) return false;
        if (!nextIsLast_) next_.wo = toward(next_, path[size_t(n + 2)]);
    }
    // R: the vertices after x_{n+1}, and the light's colour.
    for (int j = n + 2; j < k; ++j) {
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
    std::optional<SurfacePoint> traced;
    Rgb throughput(1, 1, 1);  // P
    const auto trace = [&] {
        Rgb through;
        traced = scene_.intersect(ray, nullptr, &through);
        throughput *= through;  // glazing on the way
        return traced ? &*traced : nullptr;
    };
    // The packet's primary hit knows nothing of panes: with glazing the camera ray is traced again.
    const SurfacePoint* hit = scene_.hasGlazing() ? trace() : primaryHit ? &*primaryHit : nullptr;
    for (int j = 1; j < m_; ++j) {
        if (!hit || !followSpecular(scene_, *hit, refracted_[size_t(j)], ray, throughput)) return Rgb(0, 0, 0);
        hit = trace();
    }
    if (!hit) return endsAtM_ && endsAtSky_ ? throughput * scene_.escapedRadiance(ray.direction.normalized()) : Rgb(0, 0, 0);
    PathVertex ym;
    ym.kind = VertexKind::Surface;
    ym.sp = *hit;
    ym.wo = -ray.direction.normalized();
    const ShadingMaterial& mat = scene_.material(hit->material);
    if (endsAtM_) return mat.isEmitter() ? throughput * densities_.emitted(ym, ym.wo) : Rgb(0, 0, 0);
    if (mat.isDelta() || mat.isEmitter()) return Rgb(0, 0, 0);
    const Rgb c = throughput * alongKeptDirections(ym);  // ym is y_n from here on
    if (isBlack(c) || !isFinite(c)) return Rgb(0, 0, 0);
    return keptEndsAtEmitter_ ? c : joined(ym, c);
}

Rgb LensPath::alongKeptDirections(PathVertex& y) const {
    Rgb c(1, 1, 1);
    for (size_t i = 0; i < kept_.size(); ++i) {
        const KeptDirection& d = kept_[i];
        c *= densities_.bsdf(y, d.w) * std::abs(y.sp.ng.dot(d.w));
        if (isBlack(c)) return c;
        Ray ray{y.sp.spawnOrigin(d.w), d.w};
        Rgb through;
        std::optional<SurfacePoint> hit = scene_.intersect(ray, nullptr, &through);
        c *= through;
        for (const bool refracted : d.refracted) {
            if (!hit || !followSpecular(scene_, *hit, refracted, ray, c)) return Rgb(0, 0, 0);
            hit = scene_.intersect(ray, nullptr, &through);
            c *= through;
        }
        const bool last = keptEndsAtEmitter_ && i + 1 == kept_.size();
        if (!hit) return last && endsAtSky_ ? c * scene_.escapedRadiance(ray.direction.normalized()) : Rgb(0, 0, 0);
        y.sp = *hit;
        y.wo = -ray.direction.normalized();
        const ShadingMaterial& mat = scene_.material(hit->material);
        if (last)
            return mat.isEmitter() ? c * densities_.emitted(y, y.wo) : Rgb(0, 0, 0);
        if (mat.isDelta() || mat.isEmitter()) return Rgb(0, 0, 0);
    }
    return c;
}

Rgb LensPath::joined(const PathVertex& yn, const Rgb& before) const {
    if (next_.atInfinity()) {
        // The sky keeps its direction, as a kept direction does: y_n sees it along w, or not.
        const V3f w = -next_.sp.ng;
        const Rgb c = before * densities_.bsdf(yn, w) * scene_.escapedRadiance(w) * std::abs(yn.sp.ng.dot(w));
        if (isBlack(c) || !isFinite(c)) return Rgb(0, 0, 0);
        return c * scene_.transmittance(Ray{yn.sp.spawnOrigin(w), w});
    }
    const V3f d = next_.p() - yn.p();
    const float dist2 = d.length2();
    if (!(dist2 > 0.0f)) return Rgb(0, 0, 0);
    const V3f w = d / std::sqrt(dist2);  // y_n toward x_{n+1}
    const float g = std::abs(yn.sp.ng.dot(w)) * (next_.onSurface() ? std::abs(next_.sp.ng.dot(w)) : 1.0f) / dist2;
    const Rgb atNext = nextIsLast_ ? densities_.emitted(next_, -w) : densities_.bsdf(next_, -w);
    const Rgb c = before * densities_.bsdf(yn, w) * atNext * rest_ * g;
    if (isBlack(c) || !isFinite(c)) return Rgb(0, 0, 0);
    if (next_.onSurface()) return c * scene_.transmittanceBetween(yn.sp, next_.sp);
    const V3f from = yn.sp.spawnOrigin(w);
    return c * scene_.transmittance(Ray{from, next_.p() - from, 0.0f, kShadowRayEnd});
}

}  // namespace lucerna
