#include "render/trace/warp.h"

namespace lucerna {

namespace {

inline float safeSqrt(float x) { return std::sqrt(std::max(0.0f, x)); }

}  // namespace

V2f squareToUniformDisk(const V2f& u) {
    const float x = 2.0f * u.x - 1.0f;
    const float y = 2.0f * u.y - 1.0f;
    if (x == 0.0f && y == 0.0f) return V2f(0.0f, 0.0f);
    // Map concentric squares to concentric circles, wedge by wedge; the wedge choice keeps the
    // ratio y/x or x/y in [-1, 1], so there is no division blow-up.
    float r, theta;
    if (std::abs(x) > std::abs(y)) {
        r = x;
        theta = (kPi / 4.0f) * (y / x);
    } else {
        r = y;
        theta = kPi / 2.0f - (kPi / 4.0f) * (x / y);
    }
    return V2f(r * std::cos(theta), r * std::sin(theta));
}

V3f squareToCosineHemisphere(const V2f& u) {
    const V2f d = squareToUniformDisk(u);
    // Malley: uniform on the disk, projected up, is cosine-distributed. Clamp because rounding
    // can put d just outside the unit circle.
    return V3f(d.x, d.y, safeSqrt(1.0f - d.x * d.x - d.y * d.y));
}

float cosineHemispherePdf(const V3f& w) { return w.z > 0.0f ? w.z * kInvPi : 0.0f; }

V3f squareToUniformSphere(const V2f& u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = safeSqrt(1.0f - z * z);
    const float phi = 2.0f * kPi * u.y;
    return V3f(r * std::cos(phi), r * std::sin(phi), z);
}

V3f squareToUniformHemisphere(const V2f& u) {
    const float z = u.x;
    const float r = safeSqrt(1.0f - z * z);
    const float phi = 2.0f * kPi * u.y;
    return V3f(r * std::cos(phi), r * std::sin(phi), z);
}

float uniformHemispherePdf(const V3f& w) { return w.z >= 0.0f ? 0.5f * kInvPi : 0.0f; }

V3f squareToUniformCone(const V2f& u, float cosThetaMax) {
    // Work with 1 - cos(theta) so that narrow cones (cosThetaMax near 1, e.g. a distant small
    // light) keep their precision: sin^2 = (1 - cos)(1 + cos) without the cancellation of 1 - cos^2.
    const float oneMinusCosMax = 1.0f - cosThetaMax;
    const float oneMinusCos = u.x * oneMinusCosMax;
    const float cosTheta = 1.0f - oneMinusCos;
    const float sinTheta = safeSqrt(oneMinusCos * (2.0f - oneMinusCos));
    const float phi = 2.0f * kPi * u.y;
    return V3f(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
}

float uniformConePdf(float cosThetaMax) { return 1.0f / (2.0f * kPi * (1.0f - cosThetaMax)); }

V2f squareToUniformTriangle(const V2f& u) {
    // Heitz 2019: shears the square's two halves onto the triangle; area-preserving, so the
    // density is constant and no sqrt is needed.
    float b1, b2;
    if (u.x < u.y) {
        b1 = 0.5f * u.x;
        b2 = u.y - b1;
    } else {
        b2 = 0.5f * u.y;
        b1 = u.x - b2;
    }
    return V2f(b1, b2);
}

float ggxD(const V3f& h, float alpha) {
    if (!(h.z > 0.0f)) return 0.0f;
    // With t = h.x^2 + h.y^2 and l = |h|^2, (n.h)^2 (alpha^2 - 1) + 1 = (t + alpha^2 h.z^2) / l.
    // This form needs no normalised h and avoids 1 - cos^2 cancellation near the peak, which
    // matters for small alpha where the whole lobe lives in that cancellation.
    const float a2 = alpha * alpha;
    const float t = h.x * h.x + h.y * h.y;
    const float l = t + h.z * h.z;
    const float ratio = l / (t + a2 * h.z * h.z);  // in [1, 1/alpha^2]
    return a2 * ratio * ratio * kInvPi;
}

float smithG1OverCos(const V3f& w, float alpha) {
    // G1 = 2 / (1 + sqrt(1 + a^2 tan^2)) = 2c / (c + sqrt(c^2 + a^2 s^2)) with c = |cos|, and
    // c^2 + a^2 s^2 = a^2 + (1 - a^2) c^2 for a unit w. Dividing by c analytically removes the
    // 0/0 at the horizon, where the BRDF's 1/(4 |n.wi| |n.wo|) would otherwise blow up.
    const float c = std::min(std::abs(w.z), 1.0f);
    const float a2 = alpha * alpha;
    return 2.0f / (c + std::sqrt(a2 + (1.0f - a2) * c * c));
}

float smithG1(const V3f& w, float alpha) {
    const float c = std::min(std::abs(w.z), 1.0f);
    return std::min(1.0f, c * smithG1OverCos(w, alpha));
}

V3f sampleGGXVisibleNormal(const V3f& wo, float alpha, const V2f& u) {
    // Stretch to the configuration where the microsurface is a hemisphere (alpha = 1) ...
    V3f wStd(alpha * wo.x, alpha * wo.y, std::max(wo.z, 0.0f));
    const float len = wStd.length();
    if (!(len > 0.0f)) return V3f(0.0f, 0.0f, 1.0f);
    wStd /= len;
    // ... where the visible normals are the directions c + wStd with c uniform on the spherical
    // cap z > -wStd.z of the unit sphere (Dupuy & Benyoub 2023).
    const float phi = 2.0f * kPi * u.x;
    const float z = (1.0f - u.y) * (1.0f + wStd.z) - wStd.z;
    const float sinTheta = safeSqrt(1.0f - z * z);
    const V3f hStd(sinTheta * std::cos(phi) + wStd.x, sinTheta * std::sin(phi) + wStd.y,
                   std::max(z + wStd.z, 0.0f));
    // ... and unstretch. The normal transforms with the inverse transpose: scale x, y by alpha.
    V3f h(alpha * hStd.x, alpha * hStd.y, hStd.z);
    const float hLen = h.length();
    if (!(hLen > 0.0f)) return V3f(0.0f, 0.0f, 1.0f);
    return h / hLen;
}

float ggxVisibleNormalPdf(const V3f& wo, const V3f& h, float alpha) {
    if (!(h.z > 0.0f)) return 0.0f;
    const float woDotH = wo.dot(h);
    if (!(woDotH > 0.0f)) return 0.0f;
    // G1(wo) (wo.h) D(h) / wo.z, with G1/cos evaluated in its horizon-safe form.
    return smithG1OverCos(wo, alpha) * woDotH * ggxD(h, alpha);
}

}  // namespace lucerna
