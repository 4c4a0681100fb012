#include "render/trace/lights/light_emission.h"

#include "render/trace/warp.h"

namespace lucerna {

SurfacePoint EmissionSample::surface() const {
    SurfacePoint sp;
    sp.p = position;
    sp.pError = pError;
    sp.ng = normal;
    sp.triangle = triangle;
    return sp;
}

bool emitFromTriangle(const EmitterTriangle& e, float selectPdf, const V2f& uPosition, const V2f& uDirection,
                      EmissionSample& out) {
    const V2f b = squareToUniformTriangle(uPosition);
    const float b0 = 1.0f - b.x - b.y;
    out.position = e.p0 * b0 + e.p1 * b.x + e.p2 * b.y;
    out.pError = interpolationError(e.p0, e.p1, e.p2, b0, b.x, b.y);
    out.normal = e.normal;
    out.triangle = e.triangle;
    const V3f local = squareToCosineHemisphere(uDirection);
    if (local.z <= 0.0f) return false;
    out.direction = Frame(e.normal).toWorld(local);
    out.pdfPosition = selectPdf / e.area;
    out.pdfDirection = cosineHemispherePdf(local);
    // Le cos / (pdfPosition pdfDirection) = Le pi area / selectPdf.
    out.power = e.radiance * (local.z / (out.pdfPosition * out.pdfDirection));
    return true;
}

bool emitFromDeltaLight(const DeltaLight& l, float selectPdf, float metersPerUnit, const V3f& sceneCenter,
                        float sceneRadius, const V2f& uPosition, const V2f& uDirection, EmissionSample& out,
                        const DaylightPortals* portals) {
    const float toScene = 1.0f / (metersPerUnit * metersPerUnit);
    switch (l.type) {
    case LightType::Point:
        out.position = l.position;
        out.direction = squareToUniformSphere(uDirection);
        out.pdfDirection = uniformSpherePdf();
        out.power = l.intensity * (toScene / (selectPdf * out.pdfDirection));
        break;
    case LightType::Spot: {
        out.position = l.position;
        const V3f local = squareToUniformCone(uDirection, l.cosCone);
        out.direction = Frame(l.direction).toWorld(local);
        out.pdfDirection = uniformConePdf(l.cosCone);
        const float factor = l.spotFactor(local.z);
        if (factor <= 0.0f) return false;
        out.power = l.intensity * (factor * toScene / (selectPdf * out.pdfDirection));
        break;
    }
    case LightType::Luminaire: {
        out.position = l.position;
        V3f local(0, 0, 1);
        float pdf = 0.0f;
        if (!l.goniometric || !l.goniometric->sample(uDirection, local, pdf)) return false;
        out.direction = (l.c0 * local.x + l.c90 * local.y + l.direction * local.z).normalized();
        out.pdfDirection = pdf;
        const float candela = l.goniometric->intensity(local);
        if (candela <= 0.0f) return false;
        out.power = l.intensity * (candela * toScene / (selectPdf * pdf));
        break;
    }
    case LightType::Directional: {
        // A disk of the scene's radius, facing the light, just outside the scene, or a line
        // through a window (daylight_portals.h).
        float density = 1.0f / (kPi * sceneRadius * sceneRadius);
        if (portals && !portals->empty()) {
            out.position = portals->sampleParallel(-l.direction, uPosition, density);
        } else {
            const V2f d = squareToUniformDisk(uPosition) * sceneRadius;
            const Frame frame(l.direction);
            out.position = sceneCenter - l.direction * sceneRadius + frame.s * d.x + frame.t * d.y;
        }
        out.direction = l.direction;
        out.deltaDirection = true;
        out.pdfPosition = selectPdf * density;
        out.pdfDirection = 0.0f;
        out.power = l.intensity / out.pdfPosition;
        out.normal = l.direction;
        return true;
    }
    case LightType::Sun: return false;  // never a delta light of its own (compileDeltaLight)
    }
    out.normal = out.direction;
    out.deltaPosition = true;
    out.pdfPosition = selectPdf;
    return true;
}

bool emitFromEnvironment(const EnvironmentLight& environment, float selectPdf, const V3f& sceneCenter,
                         float sceneRadius, const V2f& uPosition, const V2f& uDirection, EmissionSample& out,
                         const DaylightPortals* portals) {
    // A direction toward the sky and a line the particle travels back along, from a point
    // outside the scene: on the disc of the scene's radius facing the direction, or through a
    // window (daylight_portals.h, whose joint density is pdfDirection times the line's density).
    DaylightParticle particle;
    float lineDensity = 0;
    if (portals && !portals->empty()) {
        if (!portals->sample(uPosition, uDirection, particle)) return false;
        lineDensity = particle.lineDensity;
    } else {
        if (!environment.sample(uDirection, particle.towardSky, particle.pdfDirection, particle.radiance)) return false;
        const V2f d = squareToUniformDisk(uPosition) * sceneRadius;
        const Frame frame(particle.towardSky);
        particle.point = sceneCenter + particle.towardSky * sceneRadius + frame.s * d.x + frame.t * d.y;
        lineDensity = 1.0f / (kPi * sceneRadius * sceneRadius);
    }
    out.position = particle.point;
    out.direction = -particle.towardSky;
    out.normal = -particle.towardSky;
    out.pdfPosition = selectPdf * lineDensity;
    out.pdfDirection = particle.pdfDirection;
    out.power = particle.radiance / (out.pdfPosition * out.pdfDirection);
    out.environment = true;
    return isFinite(out.power);
}

}  // namespace lucerna
