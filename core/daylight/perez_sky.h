#pragma once
// The Perez all-weather sky of SPEC.md section 6: from one hour's direct normal and diffuse
// horizontal irradiance (a weather file's row), the sky's clearness and brightness, the
// luminous efficacies that turn the irradiances into illuminances (Perez et al. 1990), and the
// relative luminance of every sky direction (Perez, Seals and Michalsky 1993), with the
// coefficient tables Radiance's gendaymtx uses (../shared/data/perez.txt).

#include "core/math.h"

namespace lucerna {

struct PerezInputs {
    double directNormalIrradiance = 0;      // Ib, W/m^2
    double diffuseHorizontalIrradiance = 0; // Ed, W/m^2
    double dewPointC = 11;                  // Td
    int dayOfYear = 1;                      // n, 1..366
    V3d towardSun{0, 1, 0};                 // unit, the sun's true position (up is +y)
};

// The coefficients a..e of one sky (SPEC.md: x = x1 + x2 Z + Delta (x3 + x4 Z), category 1's c and
// d by their own formulas).
struct PerezCoefficients {
    double a = 0, b = 0, c = 0, d = 0, e = 0;
};

class PerezSky {
public:
    // integralResolution: of horizontalIntegral(), which sets luminanceScale() (a year of hours
    // can afford less than a scene's 256; the annual calculation states what it costs); 0: the
    // sky's shape only, luminanceScale() 0.
    explicit PerezSky(const PerezInputs& in, int integralResolution = 256);

    // Relative luminance lv toward the unit direction w above the horizon (max(lv, 0)); 0 at or
    // below it. Its scale is arbitrary: the sky's luminance is lv times luminanceScale().
    double relativeLuminance(const V3d& w) const;
    // cd/m^2 per unit of lv: the sky alone gives diffuseIlluminance() on an open horizontal plane.
    // 0 when there is no sky (Ed = 0). Where lv integrates to 0, relativeLuminance() is 1
    // everywhere (the uniform sky SPEC.md falls back to).
    double luminanceScale() const { return scale_; }
    // Luminance (cd/m^2) toward w above the horizon.
    double luminance(const V3d& w) const { return scale_ * relativeLuminance(w); }

    double diffuseIlluminance() const { return evd_; }        // Evd, lx
    double directNormalIlluminance() const { return evn_; }   // Evn, lx (0 with the sun down)
    int category() const { return category_; }                // 1..8
    double clearness() const { return epsilon_; }             // eps
    double brightness() const { return delta_; }              // Delta
    double modelZenithRad() const { return zenith_; }         // Z as the model takes it
    const PerezCoefficients& coefficients() const { return k_; }
    // lv is 0 everywhere, so the sky is uniform (relativeLuminance() 1 above the horizon).
    bool isUniform() const { return uniform_; }
    // The direction gamma is measured from: the model's zenith angle, the sun's azimuth.
    const V3d& modelTowardSun() const { return towardSun_; }

    // The integral of lv cos(zenith) over the upper hemisphere (midpoint rule on `resolution`
    // zenith rings and 4 x resolution azimuths; the gradation and circumsolar terms are smooth,
    // so 256 is within 1e-5 of the limit).
    double horizontalIntegral(int resolution = 256) const;

private:
    double lvUnclamped(double cosZeta, double gamma) const;

    int category_ = 1;
    double zenith_ = 0, epsilon_ = 0, delta_ = 0, evd_ = 0, evn_ = 0, scale_ = 0;
    bool uniform_ = false;
    PerezCoefficients k_;
    V3d towardSun_{0, 1, 0};
};

// The day number n (1..366) of a date.
int dayOfYear(int year, int month, int day);

}  // namespace lucerna
