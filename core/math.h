#pragma once
// Vector math comes from Imath (OpenEXR's). These aliases and the few helpers it lacks are the
// vocabulary of the whole code base.

#include <Imath/ImathColor.h>
#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace lucerna {

using V2f = Imath::V2f;
using V2d = Imath::V2d;
using V3f = Imath::V3f;
using V3d = Imath::V3d;
using V3i = Imath::V3i;
using M44d = Imath::M44d;
using Rgb = Imath::C3f;   // linear Rec.709, per channel
using Rgbd = Imath::Color3<double>;

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = 1.0f / kPi;

// SPEC.md: Y = 0.2126 R + 0.7152 G + 0.0722 B; 683 lm/W.
inline constexpr double kLumensPerWatt = 683.0;
inline float luminance(const Rgb& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }
inline double luminance(const Rgbd& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

inline float maxComponent(const Rgb& c) { return std::max(c.x, std::max(c.y, c.z)); }
inline bool isBlack(const Rgb& c) { return c.x == 0.0f && c.y == 0.0f && c.z == 0.0f; }
inline bool isFinite(const Rgb& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }

inline V3f toFloat(const V3d& v) { return V3f(float(v.x), float(v.y), float(v.z)); }
inline Rgb toFloat(const Rgbd& c) { return Rgb(float(c.x), float(c.y), float(c.z)); }

inline float radians(float deg) { return deg * (kPi / 180.0f); }
inline double radians(double deg) { return deg * (std::numbers::pi / 180.0); }

// Orthonormal basis around a unit normal (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited"): no branch on a threshold, so no seam where it switches.
struct Frame {
    V3f s, t, n;
    Frame() = default;
    explicit Frame(const V3f& normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        s = V3f(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        t = V3f(b, sign + n.y * n.y * a, -n.y);
    }
    V3f toLocal(const V3f& v) const { return V3f(v.dot(s), v.dot(t), v.dot(n)); }
    V3f toWorld(const V3f& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace lucerna
