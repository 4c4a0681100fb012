#pragma once
// White balance for pictures (issue 40): the colour a viewer takes as white. Linear Rec.709
// values are adapted from the chosen reference white to D65 (Rec.709's white, (1, 1, 1)) by the
// Bradford transform before the tone curve, as a camera's white balance does. Pictures only: the
// EXR's values, the lux figures and false colour are never balanced.

#include "core/math.h"
#include "core/scene/scene.h"

#include <Imath/ImathMatrix.h>

#include <string>

namespace lucerna {

enum class WhiteReference {
    D65,             // none: the values as rendered (a 4000 K lamp looks warm)
    Temperature,     // a blackbody of `kelvin`
    DominantLights,  // the scene's lights' colour, weighted by their luminous flux
};

struct WhiteBalance {
    WhiteReference reference = WhiteReference::D65;
    double kelvin = 4000;  // for Temperature
    bool operator==(const WhiteBalance&) const = default;
};

// The colour of the scene's electric lights, linear Rec.709 of luminance 1: the point, spot and
// luminaire lights that are on, their colours weighted by their luminous flux; (1, 1, 1) without
// any. Daylight and emissive surfaces are left out: a daylit room is balanced to D65, which is
// daylight's own white.
Rgbd lightsWhite(const Scene& scene);

// The linear Rec.709 colour, of luminance 1, that `balance` makes white: (1, 1, 1) for D65,
// `lights` (lightsWhite of the scene shown) for DominantLights.
Rgbd referenceWhite(const WhiteBalance& balance, const Rgbd& lights);

// The matrix on linear Rec.709 column vectors that takes `white` to (1, 1, 1) by the Bradford
// chromatic adaptation (CIE 1931 XYZ <-> Bradford's cone responses), keeping luminance of the
// white: white -> D65, and every other colour as an eye adapted to `white` would see it under
// D65. The identity for white (1, 1, 1) or a white with a channel <= 0.
Imath::M33d whiteBalanceMatrix(const Rgbd& white);

// "D65", "4000 K", "the lights (3850 K)": for status lines and tooltips.
std::string whiteBalanceLabel(const WhiteBalance& balance, const Rgbd& lights);

}  // namespace lucerna
