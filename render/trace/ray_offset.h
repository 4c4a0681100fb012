#pragma once
// Spawning rays off surfaces without self-intersection at any scene scale: the offset is the
// bound on the floating-point error of the hit point, not a fixed epsilon (pbrt-v3, section
// 3.9: the error of p = b0 p0 + b1 p1 + b2 p2 is at most gamma(7) * sum |bi pi| per axis).

#include "core/math.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace lucerna {

constexpr float gammaBound(int n) {
    constexpr float eps = std::numeric_limits<float>::epsilon() * 0.5f;
    return (n * eps) / (1 - n * eps);
}

// Absolute error bound of a point interpolated from a triangle's vertices, per axis. The
// interpolation error alone vanishes on an axis where all vertices are 0 (a wall at x = 0), but
// the ray tracer's own plane test still rounds at the scale of the largest coordinate, so that
// scale is added to every axis. A factor 2 leaves room for Embree's arithmetic.
inline V3f interpolationError(const V3f& p0, const V3f& p1, const V3f& p2, float b0, float b1, float b2) {
    const auto a = [](const V3f& v, float b) { return V3f(std::abs(v.x * b), std::abs(v.y * b), std::abs(v.z * b)); };
    const auto m = [](const V3f& v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); };
    const float scale = std::max(m(p0), std::max(m(p1), m(p2)));
    return (a(p0, b0) + a(p1, b1) + a(p2, b2) + V3f(scale)) * (2.0f * gammaBound(7));
}

// The next representable float away from zero in the direction of `sign` (finite inputs):
// std::nextafter without the library call, which showed in profiles.
inline float nextFloatToward(float v, float sign) {
    if (v == 0.0f) return sign > 0 ? std::numeric_limits<float>::denorm_min() : -std::numeric_limits<float>::denorm_min();
    const uint32_t bits = std::bit_cast<uint32_t>(v);
    const bool away = (v > 0) == (sign > 0);  // moving away from zero increases the magnitude
    return std::bit_cast<float>(away ? bits + 1 : bits - 1);
}

// Moves p off its surface (unit geometric normal n) to the side that direction w points to, far
// enough that the offset point is certainly on that side despite rounding.
inline V3f offsetRayOrigin(const V3f& p, const V3f& pError, const V3f& n, const V3f& w) {
    const float d = std::abs(n.x) * pError.x + std::abs(n.y) * pError.y + std::abs(n.z) * pError.z;
    V3f offset = n * d;
    if (w.dot(n) < 0.0f) offset = -offset;
    V3f po = p + offset;
    for (int i = 0; i < 3; ++i)
        if (offset[i] != 0.0f) po[i] = nextFloatToward(po[i], offset[i]);
    return po;
}

// A shadow ray's far end stops this fraction short of its (already offset) target point.
inline constexpr float kShadowRayEnd = 1.0f - 1e-5f;

}  // namespace lucerna
