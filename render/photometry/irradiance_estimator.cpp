#include "render/photometry/irradiance_estimator.h"

#include "render/trace/warp.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {
ShadingMaterial whiteLambertian() {
    Material m;
    m.type = MaterialType::Diffuse;
    m.albedo = Rgbd(1, 1, 1);
    return ShadingMaterial::fromMaterial(m);
}
}  // namespace

IrradianceEstimator::IrradianceEstimator(const RenderScene& scene, const GatherSettings& gather)
    : scene_(scene), white_(whiteLambertian()), pathTracer_(scene, PathSettings{}), gatherer_(scene, gather) {
    const V3f& c = scene.boundsCenter();
    errorScale_ = std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)}) + scene.boundsRadius();
}

// The sensor as a point of a surface: a sensor lying on a wall or the floor must spawn its rays
// off that surface, so its error bound is the one a surface point of this scene could have there.
float IrradianceEstimator::errorBound(const V3f& p) const {
    return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), errorScale_}) * 4.0f * gammaBound(7);
}

VplReceiver IrradianceEstimator::receiver(const IrradianceSensor& sensor) const {
    VplReceiver r;
    const V3f& p = sensor.position;
    r.x.p = p;
    r.x.pError = V3f(errorBound(p));
    r.x.ng = sensor.normal;
    r.x.triangle = 0xffffffffu;  // no triangle: nothing in the scene is excluded from its rays
    r.material = &white_;
    r.wo = sensor.normal;        // the white surface reflects toward its normal: E = pi L_o
    return r;
}

float thinPaneTransmittance(const RenderScene& scene, const Ray& shadowRay) {
    const float length = shadowRay.direction.length();
    if (!(length > 0)) return 1.0f;
    const V3f d = shadowRay.direction / length;
    Ray ray = shadowRay;
    float transmittance = 1.0f;
    for (int crossing = 0; crossing < 64; ++crossing) {
        float t = 0;
        const std::optional<SurfacePoint> hit = scene.intersect(ray, &t);
        if (!hit || !(t < ray.tFar)) return transmittance;
        const ShadingMaterial& m = scene.material(hit->material);
        if (m.type != MaterialType::Dielectric) return 0.0f;
        // cos < 0: the ray leaves the medium through this face (fresnelDielectric then uses 1 / eta).
        transmittance *= 1.0f - fresnelDielectric(-d.dot(hit->ng), m.ior);
        const V3f origin = hit->spawnOrigin(d);
        // The rest of the segment, in multiples of the original direction.
        const float travelled = (origin - ray.origin).dot(ray.direction) / ray.direction.dot(ray.direction);
        ray = Ray{origin, ray.direction, 0.0f, ray.tFar - travelled};
        if (!(ray.tFar > 0) || transmittance <= 0) return transmittance;
    }
    return 0.0f;  // a ray still in glass after 64 faces: call it blocked
}

Rgb IrradianceEstimator::deltaLightsReflected(const VplReceiver& r, bool throughPanes) const {
    const Frame frame(r.x.ng);
    // The white Lambertian surface reflects E cos(theta) / pi toward its normal.
    return deltaLightsWeighted(r, throughPanes, [&](const V3f& wi) {
        return std::max(0.0f, frame.toLocal(wi).z) / float(std::numbers::pi);
    });
}

template <class Response>
Rgb IrradianceEstimator::deltaLightsWeighted(const VplReceiver& r, bool throughPanes, const Response& response) const {
    Rgb sum(0, 0, 0);
    for (size_t i = 0; i < scene_.lights().deltaLights().size(); ++i) {
        LightSample ls;
        if (!scene_.lights().sampleDeltaLight(i, r.x, ls)) continue;
        const float weight = response(ls.wi);
        if (weight <= 0.0f) continue;
        float transmittance = 1.0f;
        const Rgb through = scene_.transmittance(ls.shadowRay);  // glazing on the way
        if (isBlack(through)) {
            if (!throughPanes) continue;
            transmittance = thinPaneTransmittance(scene_, ls.shadowRay);
            if (transmittance <= 0.0f) continue;
        }
        sum += white_.albedo * ls.value * (isBlack(through) ? Rgb(1, 1, 1) : through) * (transmittance * weight);
    }
    return sum;
}

Rgb IrradianceEstimator::deltaLightsIrradiance(const IrradianceSensor& sensor, bool throughPanes) const {
    return deltaLightsReflected(receiver(sensor), throughPanes) * float(std::numbers::pi);
}

Rgb IrradianceEstimator::deltaLightsCylindrical(const V3f& position, const V3f& axis, bool throughPanes) const {
    const V3f a = axis.normalized();
    // Ez = (1/pi) sum E_normal sin(theta): the mean over azimuths of the vertical illuminance.
    return deltaLightsWeighted(receiver({position, a}), throughPanes, [&](const V3f& wi) {
        const float c = std::clamp(wi.dot(a), -1.0f, 1.0f);
        return std::sqrt(std::max(0.0f, 1.0f - c * c)) / float(std::numbers::pi);
    });
}

IrradianceSensor IrradianceEstimator::lifted(const IrradianceSensor& sensor) const {
    // spawnOrigin() offsets by the bound's projection on the normal, at most sqrt(3) bounds.
    const V3f n = sensor.normal.normalized();
    return IrradianceSensor{sensor.position + n * (4.0f * errorBound(sensor.position)), n};
}

Rgb IrradianceEstimator::samplePath(const IrradianceSensor& sensor, Rng& rng, const Rgb* deltaE) const {
    const VplReceiver r = receiver(sensor);
    const Frame frame(sensor.normal);
    const V3f woLocal(0, 0, 1);
    Rgb Lo = deltaE ? *deltaE / float(std::numbers::pi) : deltaLightsReflected(r);

    // Area lights by next-event estimation; a delta light chosen here is already in Lo, so that
    // sample counts for nothing (the area lights' own terms keep their weights: unbiased).
    LightSample ls;
    const V2f uLight = rng.next2D();
    const float uSelect = rng.next1D();
    if (scene_.lights().sample(r.x, uLight, uSelect, ls, frame.n) && !ls.isDelta) {
        const V3f wiLocal = frame.toLocal(ls.wi);
        const Rgb f = bsdfEval(white_, woLocal, wiLocal);
        const Rgb through = isBlack(f) ? Rgb(0, 0, 0) : scene_.transmittance(ls.shadowRay);
        if (!isBlack(through))
            Lo += f * ls.value * through * (std::abs(wiLocal.z) / ls.pdf) *
                  powerHeuristic(ls.pdf, bsdfPdf(white_, woLocal, wiLocal));
    }

    BsdfSample bs;
    const V2f u = rng.next2D();
    const float uLobe = rng.next1D();
    if (bsdfSample(white_, woLocal, u, uLobe, bs)) {
        const V3f wi = frame.toWorld(bs.wi);
        const PathTracer::ScatteredFrom from{r.x.p, bs.pdf, frame.n};
        Lo += bs.weight * pathTracer_.radiance(Ray{r.x.spawnOrigin(wi), wi}, rng, &from);
    }
    return Lo * float(std::numbers::pi);
}

Rgb IrradianceEstimator::sampleVpl(const IrradianceSensor& sensor, Rng& rng, std::span<const Vpl> vpls,
                                   const Rgb* deltaE) const {
    const VplReceiver r = receiver(sensor);
    const Rgb Lo = (deltaE ? *deltaE / float(std::numbers::pi) : deltaLightsReflected(r)) + gatherer_.reflected(r, rng, vpls, {}, /*withoutDeltaLights=*/true);
    return Lo * float(std::numbers::pi);
}

}  // namespace lucerna
