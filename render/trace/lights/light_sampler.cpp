#include "render/trace/lights/light_sampler.h"

#include "render/trace/warp.h"

#include <cmath>

namespace lucerna {

LightSampler::LightSampler(std::vector<EmitterTriangle> emitters, std::vector<DeltaLight> deltas, float metersPerUnit,
                           const V3f& sceneCenter, float sceneRadius, size_t triangleCount,
                           LightSelection selection, std::optional<EnvironmentLight> environment,
                           std::vector<Portal> portals, bool particlePortals)
    : emitters_(std::move(emitters)), deltas_(std::move(deltas)), metersPerUnit_(metersPerUnit),
      sceneCenter_(sceneCenter), sceneRadius_(sceneRadius) {
    if (environment) {
        if (particlePortals) particlePortals_ = DaylightPortals(portals, *environment, sceneCenter, sceneRadius);
        environment_.emplace(std::move(*environment), std::move(portals));
    }
    power_ = PowerSelection(emitters_, deltas_, this->environment(), metersPerUnit, sceneRadius, triangleCount);
    if (selection == LightSelection::Tree && power_.size() > 1)
        tree_ = TreeSelection(emitters_, deltas_, environment_.has_value(), metersPerUnit, triangleCount);
}

bool LightSampler::sample(const SurfacePoint& ref, const V2f& u, float uSelect, LightSample& out,
                          const V3f& receiving) const {
    if (power_.empty()) return false;
    size_t index = 0;
    float selectPdf = 1.0f;
    if (!tree_.empty()) {
        if (!tree_.select(ref.p, receiving, uSelect, index, selectPdf)) return false;
    } else {
        index = power_.sample(uSelect);
        selectPdf = power_.pdf(index);
    }
    out.light = uint32_t(index);
    if (index < emitters_.size()) return sampleEmitter(emitters_[index], selectPdf, ref, u, out);
    if (isEnvironment(uint32_t(index))) return sampleEnvironment(selectPdf, ref, u, out);
    return sampleDelta(deltas_[index - emitters_.size()], selectPdf, ref, out);
}

bool LightSampler::sampleDeltaLight(size_t index, const SurfacePoint& ref, LightSample& out) const {
    if (index >= deltas_.size()) return false;
    out.light = uint32_t(emitters_.size() + index);
    return sampleDelta(deltas_[index], 1.0f, ref, out);
}

bool LightSampler::sampleEmitter(const EmitterTriangle& e, float selectPdf, const SurfacePoint& ref, const V2f& u,
                                 LightSample& out) const {
    const V2f b = squareToUniformTriangle(u);
    const float b0 = 1.0f - b.x - b.y;
    SurfacePoint q;
    q.p = e.p0 * b0 + e.p1 * b.x + e.p2 * b.y;
    q.pError = interpolationError(e.p0, e.p1, e.p2, b0, b.x, b.y);
    q.ng = e.normal;
    q.triangle = e.triangle;
    out.position = q.p;
    const V3f toLight = q.p - ref.p;
    const float dist2 = toLight.length2();
    if (!(dist2 > 0.0f)) return false;
    out.wi = toLight / std::sqrt(dist2);
    const float cosLight = -out.wi.dot(e.normal);
    if (cosLight <= 0.0f) return false;  // the back of a one-sided emitter
    out.value = e.radiance;
    out.pdf = selectPdf * dist2 / (e.area * cosLight);
    out.isDelta = false;
    const V3f from = ref.spawnOrigin(out.wi);
    const V3f to = q.spawnOrigin(-out.wi);
    out.shadowRay = Ray{from, to - from, 0.0f, kShadowRayEnd};
    return out.pdf > 0.0f && std::isfinite(out.pdf);
}

bool LightSampler::sampleDelta(const DeltaLight& l, float selectPdf, const SurfacePoint& ref, LightSample& out) const {
    out.isDelta = true;
    out.pdf = selectPdf;
    if (l.type == LightType::Directional) {
        out.wi = -l.direction;
        out.value = l.intensity;
        out.shadowRay = Ray{ref.spawnOrigin(out.wi), out.wi};
        return true;
    }
    out.position = l.position;
    const V3f toLight = l.position - ref.p;
    const float dist2 = toLight.length2();
    if (!(dist2 > 0.0f)) return false;
    out.wi = toLight / std::sqrt(dist2);
    float factor = 1.0f;
    if (l.type != LightType::Point) {
        factor = l.factor(-out.wi);
        if (factor <= 0.0f) return false;
    }
    // SPEC.md: E = I cos / (d * meters_per_unit)^2.
    out.value = l.intensity * (factor / (dist2 * metersPerUnit_ * metersPerUnit_));
    const V3f from = ref.spawnOrigin(out.wi);
    out.shadowRay = Ray{from, l.position - from, 0.0f, kShadowRayEnd};
    return true;
}

bool LightSampler::sampleEnvironment(float selectPdf, const SurfacePoint& ref, const V2f& u, LightSample& out) const {
    if (!environment_->sample(ref.p, u, out.wi, out.value)) return false;
    out.pdf = selectPdf * environment_->pdf(out.wi, ref.p);
    out.isDelta = false;
    out.position = farAlong(ref.p, out.wi);  // bidirectional connections need a place
    out.shadowRay = Ray{ref.spawnOrigin(out.wi), out.wi};
    return out.pdf > 0.0f && std::isfinite(out.pdf);
}

float LightSampler::environmentSelectPdf() const {
    if (!environment_) return 0.0f;
    return tree_.empty() ? power_.pdf(environmentIndex()) : tree_.besidePdf();
}

float LightSampler::pdfEnvironment(const V3f& w, const V3f& p) const {
    return environment_ ? environmentSelectPdf() * environment_->pdf(w, p) : 0.0f;
}

float LightSampler::pdfEnvironmentByPower(const V3f& w, const V3f& p) const {
    if (!environment_) return 0.0f;
    return power_.pdf(environmentIndex()) * environment_->pdf(w, p);
}

float LightSampler::pdfEmitter(uint32_t triangle, const V3f& p, const V3f& q, const V3f& nq,
                               const V3f& receiving) const {
    float areaPdf = power_.areaPdf(triangle);
    if (areaPdf <= 0.0f) return 0.0f;
    if (tree_.hasEmitters()) {
        areaPdf = tree_.areaPdf(triangle, p, receiving);
        if (areaPdf <= 0.0f) return 0.0f;
    }
    const V3f d = q - p;
    const float dist2 = d.length2();
    const float cosLight = std::abs(nq.dot(d)) / std::sqrt(dist2);
    if (!(cosLight > 0.0f)) return 0.0f;
    return areaPdf * dist2 / cosLight;
}

float LightSampler::environmentLineDensity(const V3f& point, const V3f& towardSky) const {
    if (particlePortals_.empty()) return 1.0f / (kPi * sceneRadius_ * sceneRadius_);
    return particlePortals_.lineDensity(point, towardSky);
}

float LightSampler::directionalLineDensity(const V3f& point, const V3f& towardLight) const {
    if (particlePortals_.empty()) return 1.0f / (kPi * sceneRadius_ * sceneRadius_);
    return particlePortals_.parallelDensity(point, towardLight);
}

float LightSampler::selectionRatio(uint32_t light, const V3f& p, const V3f& receiving) const {
    if (tree_.empty()) return 1.0f;
    const float byPower = power_.pdf(light);
    return byPower > 0.0f ? tree_.pmf(light, p, receiving) / byPower : 0.0f;
}

float LightSampler::emitterSelectionRatio(uint32_t triangle, const V3f& p, const V3f& receiving) const {
    const float byPower = power_.areaPdf(triangle);
    if (!(byPower > 0.0f)) return 0.0f;
    return tree_.hasEmitters() ? tree_.areaPdf(triangle, p, receiving) / byPower : 1.0f;
}

bool LightSampler::sampleEmission(const V2f& uPosition, const V2f& uDirection, float uSelect,
                                  EmissionSample& out) const {
    if (power_.empty()) return false;
    const size_t index = power_.sample(uSelect);  // particles leave in proportion to power, tree or not
    const float selectPdf = power_.pdf(index);
    out = EmissionSample();
    out.light = uint32_t(index);
    if (isEnvironment(uint32_t(index)))
        return emitFromEnvironment(environment_->light(), selectPdf, sceneCenter_, sceneRadius_, uPosition, uDirection,
                                   out, &particlePortals_);
    if (index < emitters_.size()) return emitFromTriangle(emitters_[index], selectPdf, uPosition, uDirection, out);
    return emitFromDeltaLight(deltas_[index - emitters_.size()], selectPdf, metersPerUnit_, sceneCenter_, sceneRadius_,
                              uPosition, uDirection, out, &particlePortals_);
}

}  // namespace lucerna
