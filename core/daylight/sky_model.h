#pragma once
// The sky luminance distributions of SPEC.md section 5: uniform, the traditional CIE overcast
// sky (Moon and Spencer 1942) and the 15 CIE general skies (ISO 15469:2004 / CIE S 011/E:2003),
// and section 6's Perez all-weather sky (perez_sky.h), relative to the zenith luminance, and
// the horizontal illuminance they give.

#include "core/daylight/perez_sky.h"
#include "core/scene/scene.h"

#include <optional>

namespace lucerna {

// The ISO 15469 parameters of CIE general sky `type` (1..15): gradation phi(Z) = 1 + a exp(b /
// cos Z), indicatrix f(chi) = 1 + c (exp(d chi) - exp(d pi / 2)) + e cos^2 chi.
struct CieSkyParameters {
    double a, b, c, d, e;
};
CieSkyParameters cieSkyParameters(int type);

// One sky's L / Lz with what does not depend on the direction worked out once (the CIE
// parameters and the normalisation f(Zs) phi(0)), for callers that evaluate many directions.
class SkyDistribution {
public:
    // towardSun: the unit direction toward the sun (cie_general and perez read it; a sun at or
    // below the horizon counts as on it for the normalisation f(Zs), as SPEC.md says). dayOfYear:
    // only perez reads it (the sun's distance, in the sky's brightness).
    SkyDistribution(const Sky& sky, const V3d& towardSun, int dayOfYear = 1);
    // L / Lz toward the unit direction w (up is +y) above the horizon (w.y > 0); 0 at or below it.
    double operator()(const V3d& w) const;
    // cie_general: 1 / (f(Zs) phi(0)); perez: 1 / lv(zenith) (1 where lv(zenith) is 0); 1 for
    // the other models.
    double normalisation() const { return normalisation_; }
    // perez: the model's quantities (its shape only: luminanceScale() is 0); nothing otherwise.
    const std::optional<PerezSky>& perez() const { return perez_; }

private:
    SkyModelType model_;
    CieSkyParameters cie_{0, -1, 0, -1, 0};
    std::optional<PerezSky> perez_;
    V3d towardSun_;
    double normalisation_ = 1;
};

// L / Lz of one direction: SkyDistribution(sky, towardSun)(w).
double relativeSkyLuminance(const Sky& sky, const V3d& w, const V3d& towardSun);

// The horizontal illuminance of the sky over its zenith luminance, Eh / Lz = integral of
// (L / Lz) cos Z over the upper hemisphere: pi for the uniform sky, 7 pi / 9 for the CIE
// overcast sky (closed forms), by the midpoint rule on `resolution` zenith rings and 4 x
// `resolution` azimuth steps for cie_general (resolution 256 is within 1e-5 of the limit).
double relativeHorizontalIlluminance(const Sky& sky, const V3d& towardSun, int resolution = 256);
// The same for a distribution made once (perez: by the midpoint rule too).
double relativeHorizontalIlluminance(const SkyDistribution& relative, int resolution = 256);

// The zenith luminance Lz (cd/m^2) the scene's sky has: its `zenith_luminance`, or the one that
// gives its `horizontal_illuminance` (SPEC.md). Not for perez, whose scale comes from its
// irradiances (daylight.h, resolveDaylight).
double zenithLuminance(const Sky& sky, const V3d& towardSun);

}  // namespace lucerna
