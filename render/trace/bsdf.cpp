#include "render/trace/bsdf.h"

#include "render/trace/warp.h"

namespace lucerna {

namespace {

// SPEC glossy specular term without the `specular` tint, for wo.z > 0 and wi.z > 0:
// D(h) G1(wi) G1(wo) / (4 wi.z wo.z), with each G1/cos in its horizon-safe form.
float ggxReflectance(const V3f& wo, const V3f& wi, float alpha) {
    const V3f h = wo + wi;  // unnormalised is fine for ggxD; h.z > 0 since both are above
    return 0.25f * ggxD(h, alpha) * smithG1OverCos(wi, alpha) * smithG1OverCos(wo, alpha);
}

// Solid-angle density of wi = reflect(wo, h) with h from sampleGGXVisibleNormal:
// D_wo(h) / (4 wo.h) = G1(wo) D(h) / (4 wo.z); the wo.h of the VNDF cancels the Jacobian's.
float ggxReflectionPdf(const V3f& wo, const V3f& wi, float alpha) {
    return 0.25f * ggxD(wo + wi, alpha) * smithG1OverCos(wo, alpha);
}

bool bothAbove(const V3f& wo, const V3f& wi) { return wo.z > 0.0f && wi.z > 0.0f; }

}  // namespace

ShadingMaterial ShadingMaterial::fromMaterial(const Material& m) {
    ShadingMaterial s;
    s.type = m.type;
    s.albedo = toFloat(m.albedo);
    s.specular = toFloat(m.specular);
    s.reflectance = toFloat(m.reflectance);
    s.radiance = toFloat(m.radiance);
    s.transmittance = toFloat(m.transmittance);
    s.alpha = std::clamp(float(m.roughness), kMinGgxAlpha, 1.0f);
    s.ior = float(m.ior);
    switch (m.type) {
    case MaterialType::Diffuse: s.diffuseLobeProb = 1.0f; break;
    case MaterialType::Glossy: {
        const bool diffuseBlack = isBlack(s.albedo), specularBlack = isBlack(s.specular);
        if (specularBlack) {
            s.diffuseLobeProb = 1.0f;  // also when both are black: nothing to sample well
        } else if (diffuseBlack) {
            s.diffuseLobeProb = 0.0f;
        } else {
            // Proportional to each lobe's (upper bound on) reflected energy, clamped so that a
            // faint lobe still gets samples: starving it would make its variance unbounded.
            const float yd = luminance(s.albedo), ys = luminance(s.specular);
            s.diffuseLobeProb = std::clamp(yd / (yd + ys), 0.1f, 0.9f);
        }
        break;
    }
    default: s.diffuseLobeProb = 0.0f; break;
    }
    return s;
}

bool ShadingMaterial::isDelta() const {
    return type == MaterialType::Mirror || type == MaterialType::Dielectric;
}

bool ShadingMaterial::isEmitter() const { return type == MaterialType::Emitter; }

Rgb bsdfEval(const ShadingMaterial& m, const V3f& wo, const V3f& wi) {
    switch (m.type) {
    case MaterialType::Diffuse:
        if (!bothAbove(wo, wi)) return Rgb(0.0f);
        return m.albedo * kInvPi;
    case MaterialType::Glossy: {
        if (!bothAbove(wo, wi)) return Rgb(0.0f);
        Rgb f = m.albedo * kInvPi;
        if (!isBlack(m.specular)) f += m.specular * ggxReflectance(wo, wi, m.alpha);
        return f;
    }
    default: return Rgb(0.0f);
    }
}

float bsdfPdf(const ShadingMaterial& m, const V3f& wo, const V3f& wi) {
    switch (m.type) {
    case MaterialType::Diffuse:
        if (!bothAbove(wo, wi)) return 0.0f;
        return wi.z * kInvPi;
    case MaterialType::Glossy: {
        if (!bothAbove(wo, wi)) return 0.0f;
        const float p = m.diffuseLobeProb;
        float pdf = 0.0f;
        if (p > 0.0f) pdf += p * wi.z * kInvPi;
        if (p < 1.0f) pdf += (1.0f - p) * ggxReflectionPdf(wo, wi, m.alpha);
        return pdf;
    }
    default: return 0.0f;
    }
}

float fresnelDielectric(float cosThetaI, float eta) {
    cosThetaI = std::clamp(cosThetaI, -1.0f, 1.0f);
    if (cosThetaI < 0.0f) {
        eta = 1.0f / eta;
        cosThetaI = -cosThetaI;
    }
    const float sin2ThetaI = std::max(0.0f, 1.0f - cosThetaI * cosThetaI);
    const float sin2ThetaT = sin2ThetaI / (eta * eta);
    if (sin2ThetaT >= 1.0f) return 1.0f;
    const float cosThetaT = std::sqrt(std::max(0.0f, 1.0f - sin2ThetaT));
    // Both denominators vanish only when cosThetaI = cosThetaT = 0, excluded above.
    const float rParl = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
    const float rPerp = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
    return std::clamp(0.5f * (rParl * rParl + rPerp * rPerp), 0.0f, 1.0f);
}

bool refractDirection(const V3f& wo, const V3f& n, float eta, V3f& wt) {
    const float cosI = std::clamp(wo.dot(n), 0.0f, 1.0f);
    const float sin2T = std::max(0.0f, 1.0f - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0f) return false;
    const float cosT = std::sqrt(1.0f - sin2T);
    // Snell: the tangential part scales by 1/eta, the normal part is -cosT.
    wt = -wo / eta + n * (cosI / eta - cosT);
    const float len = wt.length();
    if (!(len > 0.0f)) return false;
    wt /= len;
    return true;
}

bool bsdfSample(const ShadingMaterial& m, const V3f& wo, const V2f& u, float uLobe, BsdfSample& out) {
    out = BsdfSample{};
    switch (m.type) {
    case MaterialType::Diffuse: {
        if (!(wo.z > 0.0f)) return false;
        const V3f wi = squareToCosineHemisphere(u);
        if (!(wi.z > 0.0f)) return false;  // rim of the disk, rounded onto the horizon
        out.wi = wi;
        out.pdf = wi.z * kInvPi;
        out.weight = m.albedo;  // (albedo/pi) cos / (cos/pi)
        return true;
    }
    case MaterialType::Glossy: {
        if (!(wo.z > 0.0f)) return false;
        V3f wi;
        if (uLobe < m.diffuseLobeProb) {
            wi = squareToCosineHemisphere(u);
        } else {
            const V3f h = sampleGGXVisibleNormal(wo, m.alpha, u);
            wi = reflectDirection(wo, h).normalized();
        }
        if (!(wi.z > 0.0f)) return false;  // GGX reflected below the horizon: a failed sample
        // Weight from the mixture pdf (not the chosen lobe's): one-sample MIS over the lobes,
        // and the exact identity weight == eval * cos / pdf that the path tracer relies on.
        const float pdf = bsdfPdf(m, wo, wi);
        if (!(pdf > 0.0f) || !std::isfinite(pdf)) return false;
        const Rgb weight = bsdfEval(m, wo, wi) * (wi.z / pdf);
        if (!isFinite(weight)) return false;
        out.wi = wi;
        out.pdf = pdf;
        out.weight = weight;
        return true;
    }
    case MaterialType::Mirror:
        if (!(wo.z > 0.0f)) return false;
        out.wi = V3f(-wo.x, -wo.y, wo.z);
        out.weight = m.reflectance;
        out.isDelta = true;
        return true;
    case MaterialType::Dielectric: {
        // Outside (front, wo.z >= 0): light comes from vacuum into the medium, eta = ior / 1.
        // Inside: from the medium out, eta = 1 / ior. n points to wo's side.
        const bool outside = wo.z >= 0.0f;
        const float eta = outside ? m.ior : 1.0f / m.ior;
        const V3f n(0.0f, 0.0f, outside ? 1.0f : -1.0f);
        const float fr = fresnelDielectric(std::abs(wo.z), eta);
        out.isDelta = true;
        out.weight = Rgb(1.0f);  // F / F or (1 - F) / (1 - F); no tint, no eta^2 scaling
        V3f wt;
        if (uLobe < fr || !refractDirection(wo, n, eta, wt)) {
            out.wi = V3f(-wo.x, -wo.y, wo.z);
            return true;
        }
        out.wi = wt;
        out.refracted = true;
        return true;
    }
    default: return false;  // emitter: reflects nothing
    }
}

}  // namespace lucerna
