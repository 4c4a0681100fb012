#include "render/vpl/vpl_gatherer.h"

#include "render/trace/sensor_direct.h"

namespace lucerna {

namespace {
PathSettings residualPathSettings() { return PathSettings{}; }
}  // namespace

CameraVertex traceCameraVertex(const RenderScene& scene, Ray ray, SampleGenerator& u, int maxSpecularDepth, int sensorPoint) {
    CameraVertex cv;
    // Light found before any scattering, weighed against next-event estimation at a sensor's
    // point (sensor_direct.h); 1 for the pinhole, and through mirrors and glass.
    const auto directWeight = [&](int depth, const V3f& dir, const SurfacePoint* emitter) {
        return depth == 0 && sensorPoint >= 0 ? sensorRayWeight(scene, sensorPoint, dir, emitter) : 1.0f;
    };
    for (int depth = 0; depth <= maxSpecularDepth; ++depth) {
        Rgb through;
        const auto hit = scene.intersect(ray, nullptr, &through);
        cv.throughput *= through;  // glazing crossed on the way
        if (!hit) {
            // The sky seen directly or through mirrors and glass: no other strategy finds it
            // (but a sensor's next-event estimation, directly).
            const V3f dir = ray.direction.normalized();
            cv.emitted += cv.throughput * scene.escapedRadiance(dir) * directWeight(depth, dir, nullptr);
            break;
        }
        const ShadingMaterial& mat = scene.material(hit->material);
        const V3f wo = -ray.direction.normalized();
        if (mat.isEmitter()) {
            if (hit->ng.dot(wo) > 0.0f) cv.emitted += cv.throughput * mat.radiance * directWeight(depth, -wo, &*hit);
            break;
        }
        if (!mat.isDelta()) {
            cv.found = true;
            cv.receiver = VplReceiver{*hit, &mat, wo};
            break;
        }
        // Drawn only here, so that at a diffuse/glossy x1 the next numbers (a Sobol sequence's
        // stratified dimensions in the gathering pass) go to its direct light.
        const V2f ud = u.next2D();
        const float uLobe = u.next1D();
        const Frame frame(shadingNormal(mat, hit->ng, wo));
        BsdfSample bs;
        if (!bsdfSample(mat, frame.toLocal(wo), ud, uLobe, bs)) break;
        cv.throughput *= bs.weight;
        if (isBlack(cv.throughput)) break;
        const V3f wi = frame.toWorld(bs.wi);
        ray = Ray{hit->spawnOrigin(wi), wi};
    }
    return cv;
}

VplGatherer::VplGatherer(const RenderScene& scene, const GatherSettings& settings)
    : scene_(scene), settings_(settings), pathTracer_(scene, residualPathSettings()),
      maxG_(geometricClampBound(scene, settings.clampFraction)) {}

// Direct light at x1 by next-event estimation and one BSDF sample (power heuristic), directSamples
// times; the first BSDF sample also estimates the residual of the clamp and the light arriving
// through specular surfaces.
VplGatherer::Parts VplGatherer::directAndResidual(const VplReceiver& r, SampleGenerator& rng, bool withoutDeltaLights,
                                                  std::span<const Vpl> vpls, std::span<const float> scale, int directSamples) const {
    const ShadingMaterial& mat = *r.material;
    const Frame frame(shadingNormal(mat, r.x.ng, r.wo));
    const V3f woLocal = frame.toLocal(r.wo);
    const int n = std::max(1, directSamples);
    Rgb direct(0, 0, 0);
    Residual residual{vpls, scale, {}};
    for (int i = 0; i < n; ++i) direct += directSample(r, frame, woLocal, rng, withoutDeltaLights, i == 0 ? &residual : nullptr);
    residual.value.rest += direct * (1.0f / float(n));
    return residual.value;
}

VplGatherer::Parts VplGatherer::leavingX2(const VplReceiver& x2, SampleGenerator& rng, std::span<const Vpl> vpls,
                                          std::span<const float> scale) const {
    // One direct sample at x2: its light is the residual's, a small part of the pixel's.
    Parts L = directAndResidual(x2, rng, false, {}, {}, 1);
    L.vpl += gatherVpls(scene_, vpls, scale, x2, maxG_);
    return L;
}

Rgb VplGatherer::directSample(const VplReceiver& r, const Frame& frame, const V3f& woLocal, SampleGenerator& rng, bool withoutDeltaLights,
                              Residual* residual) const {
    const ShadingMaterial& mat = *r.material;
    Rgb L(0, 0, 0);

    // Next-event estimation.
    LightSample ls;
    const V2f uLight = rng.next2D();
    const float uSelect = rng.next1D();
    if (scene_.lights().sample(r.x, uLight, uSelect, ls, frame.n) && !(withoutDeltaLights && ls.isDelta)) {
        const V3f wiLocal = frame.toLocal(ls.wi);
        const Rgb f = bsdfEval(mat, woLocal, wiLocal);
        const Rgb through = isBlack(f) ? Rgb(0, 0, 0) : scene_.transmittance(ls.shadowRay);
        if (!isBlack(through)) {
            const Rgb unweighted = f * ls.value * through * (std::abs(wiLocal.z) / ls.pdf);
            L += ls.isDelta ? unweighted : unweighted * powerHeuristic(ls.pdf, bsdfPdf(mat, woLocal, wiLocal));
        }
    }

    // The BSDF sample.
    BsdfSample bs;
    const V2f u = rng.next2D();
    const float uLobe = rng.next1D();
    if (!bsdfSample(mat, woLocal, u, uLobe, bs)) return L;
    const V3f wi = frame.toWorld(bs.wi);
    const Ray ray{r.x.spawnOrigin(wi), wi};
    float t = 0;
    Rgb through;
    const auto hit = scene_.intersect(ray, &t, &through);
    if (!hit) {
        // Daylight, weighted against next-event estimation as emitters are.
        const Rgb Le = scene_.escapedRadiance(wi);
        if (!isBlack(Le)) L += bs.weight * through * Le * powerHeuristic(bs.pdf, scene_.lights().pdfEnvironment(wi, r.x.p));
        return L;
    }
    if (isBlack(through)) return L;
    const ShadingMaterial& m2 = scene_.material(hit->material);
    if (m2.isEmitter()) {
        if (hit->ng.dot(-wi) > 0.0f) {
            const float w = powerHeuristic(bs.pdf, scene_.lights().pdfEmitter(hit->triangle, r.x.p, hit->p, hit->ng, frame.n));
            L += bs.weight * through * m2.radiance * w;
        }
        return L;
    }
    if (!residual || !settings_.compensate) return L;
    float weight = 1.0f;  // through a mirror or glass: not in the VPL term at all
    if (!m2.isDelta()) {
        if (!std::isfinite(maxG_)) return L;
        const V3f d = hit->p - r.x.p;
        const float dist2 = d.length2();
        const float g = std::abs(bs.wi.z) * std::abs(hit->ng.dot(wi)) / dist2;
        weight = g > maxG_ ? 1.0f - maxG_ / g : 0.0f;
        if (!(weight > 0.0f)) return L;
    }
    // Light leaving x2 toward x1 (x2 does not emit): by the gather's terms at x2 and by a path
    // traced from it (which traces this ray again, panes included), weighed by the share.
    const float share = m2.isDelta() || residual->vpls.empty() ? 0.0f : settings_.residualVplShare;
    if (share > 0.0f) {
        const Parts atX2 = leavingX2(VplReceiver{*hit, &m2, -wi}, rng, residual->vpls, residual->scale);
        const Rgb w = bs.weight * through * (weight * share);
        residual->value.rest += w * atX2.rest;
        residual->value.vpl += w * atX2.vpl;
    }
    if (share < 1.0f) residual->value.rest += bs.weight * pathTracer_.radiance(ray, rng) * (weight * (1.0f - share));
    return L;
}

Rgb VplGatherer::radiance(const Ray& ray, SampleGenerator& rng, std::span<const Vpl> vpls, std::span<const float> scale,
                          int sensorPoint) const {
    const CameraVertex cv = traceCameraVertex(scene_, ray, rng, settings_.maxSpecularDepth, sensorPoint);
    Rgb L = cv.emitted;
    if (cv.found) L += cv.throughput * reflected(cv.receiver, rng, vpls, scale);
    // Last, so that x1's direct light keeps the numbers after the camera ray's.
    if (sensorPoint >= 0) L += sensorNextEvent(scene_, sensorPoint, rng);
    return L;
}

VplGatherer::Parts VplGatherer::radianceParts(const Ray& ray, SampleGenerator& rng, std::span<const Vpl> vpls,
                                              int sensorPoint) const {
    const CameraVertex cv = traceCameraVertex(scene_, ray, rng, settings_.maxSpecularDepth, sensorPoint);
    Parts parts{Rgb(0, 0, 0), cv.emitted};
    if (cv.found) {
        const Parts at = reflectedParts(cv.receiver, rng, vpls, {}, false);
        parts.rest += cv.throughput * at.rest;
        parts.vpl += cv.throughput * at.vpl;
    }
    if (sensorPoint >= 0) parts.rest += sensorNextEvent(scene_, sensorPoint, rng);
    return parts;
}

VplGatherer::Parts VplGatherer::reflectedParts(const VplReceiver& r, SampleGenerator& rng, std::span<const Vpl> vpls,
                                               std::span<const float> scale, bool withoutDeltaLights) const {
    Parts L = directAndResidual(r, rng, withoutDeltaLights, vpls, scale, settings_.directSamples);
    if (!vpls.empty()) L.vpl += gatherVpls(scene_, vpls, scale, r, maxG_);
    return L;
}

Rgb VplGatherer::reflected(const VplReceiver& r, SampleGenerator& rng, std::span<const Vpl> vpls, std::span<const float> scale,
                           bool withoutDeltaLights) const {
    const Parts L = reflectedParts(r, rng, vpls, scale, withoutDeltaLights);
    return L.rest + L.vpl;
}

}  // namespace lucerna
