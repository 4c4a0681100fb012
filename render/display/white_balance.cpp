#include "render/display/white_balance.h"

#include "core/photometry/light_output.h"
#include "core/photometry/luminaire.h"
#include "core/photometry/photometric_units.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {

// Linear Rec.709 (D65) to CIE 1931 XYZ, and Bradford's cone response matrix (Lam 1985, as in
// ICC v4 and Lindbloom's tables); row-major, for column vectors.
constexpr double kRgbToXyz[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                                    {0.2126729, 0.7151522, 0.0721750},
                                    {0.0193339, 0.1191920, 0.9503041}};
constexpr double kBradford[3][3] = {{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}};

// Imath multiplies row vectors (v * M), so a column-vector matrix A is stored as its transpose.
Imath::M33d columnMatrix(const double (&a)[3][3]) {
    return Imath::M33d(a[0][0], a[1][0], a[2][0], a[0][1], a[1][1], a[2][1], a[0][2], a[1][2], a[2][2]);
}

Rgbd lightColour(const Light& light) {
    const Rgbd c = light.type == LightType::Luminaire ? luminaireRadiantScale(light) : light.intensity;
    const double y = luminance(c);
    return y > 0 ? c / y : Rgbd(0, 0, 0);
}

double lightFlux(const Light& light) {
    switch (light.type) {
    case LightType::Point:
    case LightType::Spot: return luminousFluxLm(light);
    case LightType::Luminaire: return luminaireFlux(light);
    default: return 0;
    }
}

// The correlated colour temperature of a white (McCamy 1992, from its CIE 1931 xy; within a few
// kelvin of the Planckian locus from 2,000 to 12,500 K), for labels only.
double correlatedTemperatureK(const Rgbd& white) {
    const V3d xyz = V3d(white.x, white.y, white.z) * columnMatrix(kRgbToXyz);
    const double s = xyz.x + xyz.y + xyz.z;
    if (!(s > 0)) return 0;
    const double n = (xyz.x / s - 0.3320) / (0.1858 - xyz.y / s);
    return 449.0 * n * n * n + 3525.0 * n * n + 6823.3 * n + 5520.33;
}

}  // namespace

Rgbd lightsWhite(const Scene& scene) {
    Rgbd sum(0, 0, 0);
    for (const Light& l : scene.lights) {
        if (!l.on) continue;
        const double flux = lightFlux(l);
        if (std::isfinite(flux) && flux > 0) sum += lightColour(l) * flux;
    }
    const double y = luminance(sum);
    return y > 0 ? sum / y : Rgbd(1, 1, 1);
}

Rgbd referenceWhite(const WhiteBalance& balance, const Rgbd& lights) {
    switch (balance.reference) {
    case WhiteReference::Temperature: return blackbodyColour(std::clamp(balance.kelvin, 1000.0, 40000.0));
    case WhiteReference::DominantLights: return lights;
    case WhiteReference::D65: break;
    }
    return Rgbd(1, 1, 1);
}

// M = RGB<-XYZ B^-1 diag(B XYZ(D65) / B XYZ(white)) B XYZ<-RGB (von Kries in Bradford's cone
// space). XYZ(D65) is the XYZ of (1, 1, 1); white has luminance 1 like it, so Y is kept.
Imath::M33d whiteBalanceMatrix(const Rgbd& white) {
    if (!(white.x > 0 && white.y > 0 && white.z > 0) || (white.x == white.y && white.y == white.z))
        return Imath::M33d();  // identity
    const Imath::M33d toXyz = columnMatrix(kRgbToXyz), bradford = columnMatrix(kBradford);
    const Imath::M33d toCone = toXyz * bradford;  // row vectors: first to XYZ, then to cones
    const V3d from = V3d(white.x, white.y, white.z) * toCone, to = V3d(1, 1, 1) * toCone;
    Imath::M33d gain;  // diagonal
    gain[0][0] = to.x / from.x;
    gain[1][1] = to.y / from.y;
    gain[2][2] = to.z / from.z;
    return toCone * gain * toCone.inverse();
}

std::string whiteBalanceLabel(const WhiteBalance& balance, const Rgbd& lights) {
    switch (balance.reference) {
    case WhiteReference::Temperature: return std::to_string(std::lround(balance.kelvin)) + " K";
    case WhiteReference::DominantLights: {
        const double k = correlatedTemperatureK(lights);
        return "the lights (" + (k > 0 ? std::to_string(std::lround(k / 10) * 10) + " K" : std::string("D65")) + ")";
    }
    case WhiteReference::D65: break;
    }
    return "D65";
}

}  // namespace lucerna
