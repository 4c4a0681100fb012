#include "core/photometry/photometric_units.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {


// Wyman, Sloan and Shirley 2013, "Simple Analytic Approximations to the CIE XYZ Color Matching
// Functions": piecewise Gaussians g(lambda; mu, sigma below mu, sigma above mu).
double lobe(double lambda, double mu, double below, double above) {
    const double t = (lambda - mu) / (lambda < mu ? below : above);
    return std::exp(-0.5 * t * t);
}
double cieX(double l) {
    return 1.056 * lobe(l, 599.8, 37.9, 31.0) + 0.362 * lobe(l, 442.0, 16.0, 26.7) - 0.065 * lobe(l, 501.1, 20.4, 26.2);
}
double cieY(double l) { return 0.821 * lobe(l, 568.8, 46.9, 40.5) + 0.286 * lobe(l, 530.9, 16.3, 31.1); }
double cieZ(double l) { return 1.217 * lobe(l, 437.0, 11.8, 36.0) + 0.681 * lobe(l, 459.0, 26.0, 13.8); }

// Planck's spectral radiance, up to a constant factor (normalised away).
double planck(double lambdaNm, double kelvin) {
    constexpr double c2 = 1.4387769e7;  // h c / k in nm K
    const double l = lambdaNm;
    return 1.0 / (l * l * l * l * l * (std::exp(c2 / (l * kelvin)) - 1.0));
}

}  // namespace

Rgbd blackbodyColour(double kelvin) {
    double X = 0, Y = 0, Z = 0;
    for (double l = 360.0; l <= 830.0; l += 1.0) {
        const double b = planck(l, kelvin);
        X += b * cieX(l);
        Y += b * cieY(l);
        Z += b * cieZ(l);
    }
    Rgbd rgb(3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z, -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z,
             0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z);
    rgb = Rgbd(std::max(0.0, rgb.x), std::max(0.0, rgb.y), std::max(0.0, rgb.z));
    return rgb / luminance(rgb);
}

double pointSolidAngle() { return 4.0 * std::numbers::pi; }

double spotSolidAngle(double coneAngleDeg, std::optional<double> falloffStartDeg) {
    const double toRad = std::numbers::pi / 180.0;
    const double a = std::cos(coneAngleDeg * toRad);
    const double b = std::cos(falloffStartDeg.value_or(coneAngleDeg) * toRad);
    return 2.0 * std::numbers::pi * ((1.0 - b) + 0.5 * (b - a));
}

Rgbd photometricIntensity(const PhotometricSpec& spec, double solidAngle) {
    const Rgbd colour = spec.temperatureK ? blackbodyColour(*spec.temperatureK)
                                          : spec.colour.value_or(Rgbd(1, 1, 1)) / luminance(spec.colour.value_or(Rgbd(1, 1, 1)));
    const double candela = spec.quantity == PhotometricSpec::Quantity::Candela ? spec.value : spec.value / solidAngle;
    return colour * (candela / kLumensPerWatt);
}

}  // namespace lucerna
