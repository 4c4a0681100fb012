#pragma once
// Warps from the unit square [0,1)^2 to the domains a path tracer samples, each with the density
// it produces (pbrt-v4 style, chapter A.5). All functions are pure: the same u gives the same
// point on every thread and every run, which keeps renders reproducible bit for bit.
//
// Conventions: directions are unit vectors in a local frame whose +z is the normal (or the cone
// axis); densities over directions are per steradian (solid angle), densities over planar domains
// are per unit area of that domain. u is expected in [0,1)^2; values of exactly 1 are tolerated.
//
// The GGX functions implement SPEC.md section 1 ("glossy") exactly:
//   D(h)  = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2)
//   G1(w) = 2 / (1 + sqrt(1 + alpha^2 tan^2 theta_w))        (separable Smith, no Fresnel)
// and that G1 is the exact Smith masking function of that D, which is what makes sampling the
// visible normals exact (its density integrates to 1).

#include "core/math.h"

namespace lucerna {

// --- Disk --------------------------------------------------------------------------------------

// Concentric map (Shirley & Chiu 1997) onto the unit disk; low distortion, continuous.
V2f squareToUniformDisk(const V2f& u);
inline float uniformDiskPdf() { return kInvPi; }  // per unit area of the unit disk

// --- Hemisphere and sphere ---------------------------------------------------------------------

// Cosine-weighted hemisphere around +z (Malley's method on the concentric disk). z >= 0.
V3f squareToCosineHemisphere(const V2f& u);
// cos(theta) / pi for w.z > 0, else 0.
float cosineHemispherePdf(const V3f& w);

// Uniform over the whole unit sphere.
V3f squareToUniformSphere(const V2f& u);
inline float uniformSpherePdf() { return 0.25f * kInvPi; }

// Uniform over the hemisphere z >= 0.
V3f squareToUniformHemisphere(const V2f& u);
// 1 / (2 pi) for w.z >= 0, else 0.
float uniformHemispherePdf(const V3f& w);

// --- Cone --------------------------------------------------------------------------------------

// Uniform over the directions within angle thetaMax of +z; cosThetaMax in [-1, 1).
V3f squareToUniformCone(const V2f& u, float cosThetaMax);
// 1 / (2 pi (1 - cosThetaMax)) for directions inside the cone (the caller tests membership:
// w.z >= cosThetaMax). Precondition: cosThetaMax < 1.
float uniformConePdf(float cosThetaMax);

// --- Triangle ----------------------------------------------------------------------------------

// Uniform barycentrics (b1, b2) on a triangle, b1, b2 >= 0, b1 + b2 <= 1; the point is
// (1 - b1 - b2) v0 + b1 v1 + b2 v2. Uses Heitz's area-preserving low-distortion map (2019,
// "A Low-Distortion Map Between Triangle and Square"), so stratification of u carries over.
// Density: 2 per unit area of the (b1, b2) plane, i.e. 1 / area of the actual triangle.
V2f squareToUniformTriangle(const V2f& u);

// --- GGX (SPEC glossy lobe) --------------------------------------------------------------------

// Normal distribution D(h) of the SPEC formula; h need not be normalised (only its direction
// matters); 0 for h.z <= 0. alpha in (0, 1]. Per steradian of microfacet normals, projected:
// the integral of D(h) h.z over the hemisphere is 1.
float ggxD(const V3f& h, float alpha);

// Smith masking G1(w) of the SPEC formula, in [0, 1]; depends on |w.z| only (two-sided, no
// microfacet side test: SPEC has none). G1 = 0 on the horizon. w unit.
float smithG1(const V3f& w, float alpha);

// G1(w) / |w.z|, evaluated without the 0/0 at the horizon (it tends to 2 / alpha there).
// Equal to 2 / (|c| + sqrt(alpha^2 + (1 - alpha^2) c^2)) with c = w.z.
float smithG1OverCos(const V3f& w, float alpha);

// Samples a microfacet normal h (h.z >= 0, unit) from the distribution of normals visible from
// wo, D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z (Heitz 2018), by the spherical-cap method of
// Dupuy & Benyoub 2023 (same distribution, no branches, no seam). Precondition: wo unit,
// wo.z >= 0 (wo exactly on the horizon is allowed).
V3f sampleGGXVisibleNormal(const V3f& wo, float alpha, const V2f& u);

// Exact density (per steradian of h) of sampleGGXVisibleNormal; 0 for h.z <= 0 or wo.h <= 0.
float ggxVisibleNormalPdf(const V3f& wo, const V3f& h, float alpha);

// Mirror reflection of wo about the unit normal n: 2 (wo.n) n - wo (both pointing away from the
// surface; the result is unit when both are).
inline V3f reflectDirection(const V3f& wo, const V3f& n) { return n * (2.0f * wo.dot(n)) - wo; }

}  // namespace lucerna
