#pragma once
// The SPEC.md section 1 materials as BSDFs, evaluated and sampled in their local shading frame
// (+z = normal). All functions are pure and thread-safe.
//
// Frame conventions (the caller's job):
//   - diffuse, glossy, mirror are two-sided: the caller flips the frame so that wo.z > 0. With
//     wo.z <= 0 (including wo exactly on the horizon) eval and pdf return 0 and sample fails.
//   - dielectric is one-sided: +z is the FRONT side (vacuum, index 1), -z the medium of index
//     `ior`. Do not flip its frame: wo.z < 0 means wo is inside the medium.
//   - emitter: reflects nothing (eval/pdf 0, sample fails); its emission is the caller's business.
//
// Radiometry: f is in sr^-1, without the cosine. The sample weight already contains the cosine
// and the pdf, so throughput *= weight is all a path tracer does.

#include "core/math.h"
#include "core/scene/scene.h"

namespace lucerna {

struct ShadingMaterial {  // the float, render-time form of a Material
    MaterialType type = MaterialType::Diffuse;
    Rgb albedo{0, 0, 0}, specular{0, 0, 0}, reflectance{0, 0, 0}, radiance{0, 0, 0};
    Rgb transmittance{1, 1, 1};  // glazing
    float alpha = 0.5f;  // GGX roughness, in [kMinGgxAlpha, 1]
    float ior = 1.5f;    // dielectric: index of the medium behind the front face, > 0
    float diffuseLobeProb = 1.0f;  // glossy: probability of sampling the Lambert lobe (derived in fromMaterial)

    // Converts to float; clamps alpha to [kMinGgxAlpha, 1] and derives diffuseLobeProb:
    // luminance(albedo) / (luminance(albedo) + luminance(specular)), kept within [0.1, 0.9] when
    // both lobes are non-black (so neither lobe is starved of samples), 1 when specular is black,
    // 0 when albedo is black (1 when both are). Diffuse: 1; other types: 0 (unused).
    static ShadingMaterial fromMaterial(const Material& m);
    bool isDelta() const;  // mirror, dielectric: no non-delta component at all
    bool isEmitter() const;
};

// Roughness below this is clamped: D peaks at 1 / (pi alpha^2) and its denominator goes as
// alpha^4, which underflows float well before alpha reaches 0. 1e-4 is visually a mirror.
inline constexpr float kMinGgxAlpha = 1e-4f;

struct BsdfSample {
    V3f wi;           // local frame, unit
    Rgb weight;       // f * |cos theta_i| / pdf for a non-delta sample; for a delta lobe, its throughput (reflectance, or 1 for glass) -- Fresnel lobe choice already divided out
    float pdf = 0;    // solid-angle pdf (0 meaning "delta" when isDelta)
    bool isDelta = false;
    bool refracted = false;
};

// f(wo, wi) of the non-delta part (no cosine), in sr^-1. Diffuse, glossy, mirror are two-sided:
// the CALLER flips the frame so that wo.z > 0; eval returns 0 when wi.z <= 0 or wo.z <= 0 for
// them. Dielectric/mirror return 0 (delta only). Emitter: 0. Symmetric: f(wo, wi) == f(wi, wo).
Rgb bsdfEval(const ShadingMaterial& m, const V3f& wo, const V3f& wi);

// Solid-angle pdf with which bsdfSample returns wi (non-delta part, the lobe mixture included).
// 0 for delta materials and emitters. For glossy it integrates to less than 1 over the
// hemisphere: GGX samples that reflect below the horizon are failures, not renormalised.
float bsdfPdf(const ShadingMaterial& m, const V3f& wo, const V3f& wi);

// Samples wi. u for the direction, uLobe in [0,1) for the lobe/Fresnel choice (independent of u).
// false = no sample (absorbed / below horizon / wo.z <= 0 for two-sided materials / emitter).
// Non-delta results: pdf == bsdfPdf(m, wo, wi) > 0 and weight == bsdfEval * wi.z / pdf (finite,
// >= 0; bit for bit for glossy, up to float rounding for diffuse, whose weight is albedo exactly);
// wi.z > 0. Glossy weights come from the mixture pdf (one-sample MIS over the two lobes).
// Dielectric: +z is the FRONT side (vacuum); wo.z < 0 means wo is inside the medium of index ior.
// Exact unpolarised Fresnel; reflect with probability F, else refract (total internal reflection
// -> reflect, weight 1); radiance NOT scaled by eta^2, so the weight is always 1.
bool bsdfSample(const ShadingMaterial& m, const V3f& wo, const V2f& u, float uLobe, BsdfSample& out);

// The shading normal at a hit with unit geometric normal ng seen from wo: two-sided materials
// shade with ng flipped toward wo (SPEC.md); glass keeps its front side, which tells entering
// from leaving.
inline V3f shadingNormal(const ShadingMaterial& mat, const V3f& ng, const V3f& wo) {
    if (mat.type == MaterialType::Dielectric) return ng;
    return ng.dot(wo) < 0.0f ? -ng : ng;
}

// Unpolarised Fresnel reflectance of a smooth dielectric interface, in [0, 1]. cosThetaI is the
// cosine between the incident direction and the normal; eta = n_transmitted / n_incident for
// cosThetaI >= 0. A negative cosThetaI means the incident direction is on the other side, and
// 1 / eta is used (pbrt-v4 FrDielectric). Returns 1 under total internal reflection.
float fresnelDielectric(float cosThetaI, float eta);

// Refracts wo (unit, pointing away from the surface, on the side of the unit normal n:
// wo.n >= 0) through an interface with eta = n_transmitted / n_incident. Writes the unit
// transmitted direction (on the other side of n) and returns true; false under total internal
// reflection.
bool refractDirection(const V3f& wo, const V3f& n, float eta, V3f& wt);

}  // namespace lucerna
