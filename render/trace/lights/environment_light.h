#pragma once
// Daylight as an emitter at infinity (SPEC.md section 5): the sky above the horizon, the ground
// below it, and the sun's disc when it has a size (a sun of diameter 0 is a directional light).
// Directions are sampled from a table of the sky's luminance built once (equal-area cells in
// (cos theta, phi) about +y) mixed with uniform sampling of the sun's cone, in proportion to
// their power; pdf() is the mixture's density, for MIS with BSDF sampling.

#include "core/daylight/daylight.h"
#include "render/trace/discrete_distribution.h"

#include <functional>
#include <optional>
#include <vector>

namespace lucerna {

class EnvironmentLight {
public:
    // The sky and the sun's disc of `daylight`; nullopt when neither gives light (no sky, a dark
    // one, a delta sun, a sun below the horizon).
    static std::optional<EnvironmentLight> fromDaylight(const Daylight& daylight);

    // Radiance (W sr^-1 m^-2) arriving along -w, for unit w pointing out of the scene.
    Rgb radiance(const V3f& w) const;
    // A direction w (unit, out of the scene) with its solid-angle density and the radiance
    // arriving from it; false when nothing could be sampled.
    bool sample(const V2f& u, V3f& w, float& pdf, Rgb& value) const;
    // The solid-angle density with which sample() yields w.
    float pdf(const V3f& w) const;
    // Integral of luminance(radiance) over all directions (W m^-2 per unit luminance weight):
    // times pi R^2, the power of the particles leaving a disc of radius R facing each direction.
    double integratedLuminance() const { return skyIntegral_ + sunIntegral_; }
    // The same light sampled in proportion to its table times factor(w) >= 0 (taken at each
    // cell's centre, and at the sun's centre for its whole disc): sample() and pdf() then draw
    // and give that density, radiance() is unchanged and integratedLuminance() integrates the
    // luminance times the factor. Daylight portals draw directions by the windows' projected area.
    EnvironmentLight reweighted(const std::function<double(const V3d&)>& factor) const;
    // Whether it has a sky (or ground) to sample, beside the sun's disc.
    bool hasSky() const { return !rows_.empty(); }

private:
    bool insideSun(const V3f& w) const;
    float skyPdf(const V3f& w) const;

    std::optional<ResolvedSky> sky_;
    std::optional<SkyDistribution> skyRelative_;  // sky_'s, made once: radiance() runs for every escaping ray
    // The sun's disc: its centre direction, 1 - cos and sin^2 of its half-angle (kept apart from
    // cos itself: for 0.53 degrees 1 - cos is 1.1e-5, below a float's resolution near 1).
    V3f towardSun_{0, 1, 0};
    float sunOneMinusCos_ = 0, sunSin2_ = 0;
    Rgb sunRadiance_{0, 0, 0};
    // The sky table: rows in y = cos theta from +1 down to -1, columns in phi; equal solid angles.
    static constexpr int kRows = 64, kColumns = 128;
    DiscreteDistribution rows_;
    std::vector<DiscreteDistribution> columns_;
    double skyIntegral_ = 0, sunIntegral_ = 0;
    float sunProbability_ = 0;
};

}  // namespace lucerna
