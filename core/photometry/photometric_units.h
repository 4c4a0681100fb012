#pragma once
// Photometric light specifications (an extension of SPEC.md, documented in the README): point
// and spot lights given in lumens or candela, with a colour or a blackbody temperature, converted
// to the radiant intensity (W/sr per RGB channel) that every backend uses. Conversion by SPEC.md's
// 683 lm/W and Rec.709 luminance: a colour normalised to luminance 1 times I_v / 683.

#include "core/math.h"

#include <optional>

namespace lucerna {

struct PhotometricSpec {
    enum class Quantity { Lumens, Candela };
    Quantity quantity = Quantity::Lumens;
    double value = 0;                    // lm (total flux) or cd (on-axis luminous intensity)
    std::optional<Rgbd> colour;          // any non-black colour; normalised to luminance 1
    std::optional<double> temperatureK;  // a blackbody's colour instead

    bool operator==(const PhotometricSpec&) const = default;
};

// Linear Rec.709 colour of a blackbody at `kelvin`, normalised to luminance 1: Planck's law
// weighted by the CIE 1931 colour matching functions (Wyman, Sloan and Shirley's 2013 analytic
// fit, within about 1% of the tables), XYZ to linear Rec.709, negative channels clipped.
Rgbd blackbodyColour(double kelvin);

// The effective solid angle of a light's distribution, Omega = (1 / I_0) integral I(w) dw, so
// that flux = I_0 Omega: 4 pi for a point light; for a spot with cosines a = cos(cone) and
// b = cos(falloff start), 2 pi ((1 - b) + (b - a) / 2) (SPEC.md's smoothstep integrates to half
// its range), 2 pi (1 - a) with a hard edge.
double pointSolidAngle();
double spotSolidAngle(double coneAngleDeg, std::optional<double> falloffStartDeg);

// Radiant intensity (W/sr, on axis) of a light with this specification and distribution
// solid angle.
Rgbd photometricIntensity(const PhotometricSpec& spec, double solidAngle);

}  // namespace lucerna
