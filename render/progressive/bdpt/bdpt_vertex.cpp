#include "render/progressive/bdpt/bdpt_vertex.h"

#include "render/trace/warp.h"

namespace lucerna {

VertexDensities::VertexDensities(const RenderScene& scene) : scene_(scene) {}

float VertexDensities::toArea(float pdfSolidAngle, const PathVertex& from, const PathVertex& to) {
    if (to.atInfinity()) return pdfSolidAngle;  // a direction, not a place
    const V3f w = to.p() - from.p();
    const float dist2 = w.length2();
    if (!(dist2 > 0.0f)) return 0.0f;
    float pdf = pdfSolidAngle / dist2;
    if (to.onSurface()) pdf *= std::abs(to.sp.ng.dot(w)) / std::sqrt(dist2);
    return pdf;
}

float VertexDensities::bsdfPdf(const PathVertex& v, const V3f& wFrom, const V3f& wTo) const {
    const ShadingMaterial& mat = scene_.material(v.sp.material);
    const Frame frame(shadingNormal(mat, v.sp.ng, wFrom));
    return lucerna::bsdfPdf(mat, frame.toLocal(wFrom), frame.toLocal(wTo));
}

Rgb VertexDensities::bsdf(const PathVertex& v, const V3f& wi) const {
    const ShadingMaterial& mat = scene_.material(v.sp.material);
    const Frame frame(shadingNormal(mat, v.sp.ng, v.wo));
    return bsdfEval(mat, frame.toLocal(v.wo), frame.toLocal(wi));
}

float VertexDensities::pdf(const PathVertex& v, const PathVertex* prev, const PathVertex& next) const {
    if (v.kind != VertexKind::Camera && v.kind != VertexKind::Surface) return pdfLight(v, next);
    const V3f d = next.p() - v.p();
    const float len = d.length();
    if (!(len > 0.0f)) return 0.0f;
    const V3f wn = d / len;
    if (v.kind == VertexKind::Camera) return toArea(cameraPdfDirection(int(v.light), wn), v, next);
    if (!prev) return 0.0f;
    const V3f wp = (prev->p() - v.p()).normalized();
    return toArea(bsdfPdf(v, wp, wn), v, next);
}

float VertexDensities::pdfLight(const PathVertex& v, const PathVertex& next) const {
    const V3f d = next.p() - v.p();
    const float dist2 = d.length2();
    if (!(dist2 > 0.0f)) return 0.0f;
    const V3f w = d / std::sqrt(dist2);
    float pdf = 0.0f;
    switch (v.kind) {
    case VertexKind::Surface:  // an emitter hit by a camera subpath: cosine-weighted emission
    case VertexKind::AreaLight: {
        const float cosLight = v.sp.ng.dot(w);
        if (cosLight <= 0.0f) return 0.0f;
        pdf = cosLight * kInvPi / dist2;
        break;
    }
    case VertexKind::PointLight:
    case VertexKind::SpotLight:
    case VertexKind::Luminaire: {
        const DeltaLight& l = scene_.lights().deltaLights()[v.light - scene_.lights().emitters().size()];
        pdf = l.pdfDirection(w) / dist2;
        if (!(pdf > 0.0f)) return 0.0f;
        break;
    }
    case VertexKind::DirectionalLight: {
        // Parallel rays from a disk or through a window: the area density across the line,
        // projected (no 1/d^2).
        const DeltaLight& l = scene_.lights().deltaLights()[v.light - scene_.lights().emitters().size()];
        const float across = scene_.lights().directionalLineDensity(next.p(), -l.direction);
        return next.onSurface() ? across * std::abs(next.sp.ng.dot(l.direction)) : across;
    }
    case VertexKind::EnvironmentLight: {  // the line through next, from the disk or a window
        const float across = scene_.lights().environmentLineDensity(next.p(), -v.sp.ng);
        return next.onSurface() ? across * std::abs(next.sp.ng.dot(v.sp.ng)) : across;
    }
    case VertexKind::Camera: return 0.0f;
    }
    if (next.onSurface()) pdf *= std::abs(next.sp.ng.dot(w));
    return pdf;
}

float VertexDensities::pdfLightOrigin(const PathVertex& v, const PathVertex* next) const {
    if (v.atInfinity()) return next ? scene_.lights().pdfEnvironmentByPower(-v.sp.ng, next->p()) : 0.0f;
    if (v.kind != VertexKind::AreaLight && v.kind != VertexKind::Surface) return 0.0f;
    // By power even where next-event estimation chooses lights by the tree: the weights of all
    // strategies then use one density for the origin and still sum to one (light_sampler.h).
    return scene_.lights().areaPdfByPower(v.sp.triangle);
}

Rgb VertexDensities::emitted(const PathVertex& v, const V3f& w) const {
    const LightSampler& lights = scene_.lights();
    switch (v.kind) {
    case VertexKind::Surface:
    case VertexKind::AreaLight: {
        const ShadingMaterial& mat = scene_.materialOfTriangle(v.sp.triangle);
        return mat.isEmitter() && v.sp.ng.dot(w) > 0.0f ? mat.radiance : Rgb(0, 0, 0);
    }
    case VertexKind::PointLight:
    case VertexKind::SpotLight:
    case VertexKind::Luminaire: {
        const DeltaLight& l = lights.deltaLights()[v.light - lights.emitters().size()];
        const float mpu = scene_.metersPerUnit();
        return l.intensity * (l.factor(w) / (mpu * mpu));
    }
    case VertexKind::EnvironmentLight: return scene_.escapedRadiance(-w);
    default: return Rgb(0, 0, 0);
    }
}

}  // namespace lucerna
