#include "render/preview/preview_vpls.h"

#include "render/trace/rng.h"

namespace lucerna {

DeltaLight compileDeltaLight(const Light& l) {
    DeltaLight d;
    d.type = l.type;
    d.position = toFloat(l.position);
    d.direction = toFloat(l.direction.normalized());
    d.intensity = toFloat(l.type == LightType::Directional ? l.irradiance : l.intensity);
    if (l.type == LightType::Spot) {
        d.cosCone = float(std::cos(radians(l.coneAngleDeg)));
        d.cosFalloffStart = float(std::cos(radians(l.falloffStartDeg.value_or(l.coneAngleDeg))));
    }
    return d;
}

LightSampler singleLightSampler(const RenderScene& scene, const DeltaLight* delta) {
    std::vector<EmitterTriangle> emitters;
    std::vector<DeltaLight> deltas;
    if (delta)
        deltas.push_back(*delta);
    else
        emitters = scene.lights().emitters();
    return LightSampler(std::move(emitters), std::move(deltas), scene.metersPerUnit(), scene.boundsCenter(),
                        scene.boundsRadius(), scene.triangleCount());
}

VplSet traceVpls(const RenderScene& scene, const LightSampler& source, int count, uint64_t seed, int maxBounces) {
    VplSet vpls;
    if (source.empty() || count <= 0) return vpls;
    vpls.reserve(size_t(count));
    Rng rng(seed, 0x5eedULL);
    const long maxPaths = 64L * count;
    long paths = 0;
    while (int(vpls.size()) < count && paths < maxPaths) {
        ++paths;
        EmissionSample e;
        const V2f u0 = rng.next2D(), u1 = rng.next2D();
        if (!source.sampleEmission(u0, u1, rng.next1D(), e)) continue;
        Rgb beta = e.power;
        Ray ray{e.triangle != 0xffffffffu ? e.surface().spawnOrigin(e.direction) : e.position, e.direction};
        for (int bounce = 1; bounce <= maxBounces && int(vpls.size()) < count; ++bounce) {
            const auto hit = scene.intersect(ray);
            if (!hit) break;
            const ShadingMaterial& m = scene.material(hit->material);
            if (m.isEmitter()) break;
            const V3f wo = -ray.direction;
            // Two-sided: the frame faces the side the light arrived on.
            const V3f n = hit->ng.dot(wo) >= 0 ? hit->ng : -hit->ng;
            if (!m.isDelta()) {
                Vpl v;
                v.position = hit->p;
                v.normal = n;
                v.incident = wo;
                v.power = beta;  // divided by the path count at the end
                v.material = hit->material;
                v.triangle = hit->triangle;
                v.bounce = bounce;
                vpls.push_back(v);
            }
            const Frame frame(n);
            BsdfSample s;
            if (!bsdfSample(m, frame.toLocal(wo), rng.next2D(), rng.next1D(), s)) break;
            beta *= s.weight;
            // Russian roulette after the third bounce keeps long paths cheap and unbiased.
            if (bounce >= 3) {
                const float q = std::min(0.95f, std::max({beta.x, beta.y, beta.z}) /
                                                     std::max(1e-30f, std::max({e.power.x, e.power.y, e.power.z})));
                if (rng.next1D() >= q) break;
                beta /= q;
            }
            const V3f wi = frame.toWorld(s.wi);
            ray = Ray{hit->spawnOrigin(wi), wi};
        }
    }
    const float inv = 1.0f / float(paths);
    for (Vpl& v : vpls) v.power *= inv;
    return vpls;
}

}  // namespace lucerna
