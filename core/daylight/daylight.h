#pragma once
// A scene's daylight resolved into what renderers emit (SPEC.md section 5): the sun's direction
// and the radiance of its disc, the sky's zenith luminance and the ground's luminance. Luminance
// becomes radiance by SPEC.md's 683 lm/W: sky and ground are white, the sun takes its colour
// normalised to luminance 1.

#include "core/scene/scene.h"
#include "core/daylight/sky_model.h"

#include <optional>

namespace lucerna {


struct ResolvedSun {
    V3d towardSun{0, 1, 0};      // unit world direction toward the sun
    double illuminanceLux = 0;   // direct normal illuminance
    double halfAngleRad = 0;     // of the disc; 0: a delta light
    Rgbd colour{1, 1, 1};        // luminance 1
    bool aboveHorizon = false;   // a sun at or below the horizon gives no light

    // Normal irradiance per channel, W/m^2 (0 below the horizon).
    Rgbd irradiance() const;
    // Radiance of the disc per channel, W sr^-1 m^-2: illuminance / (683 pi sin^2(d/2)); 0 for a
    // delta sun or one below the horizon.
    Rgbd radiance() const;
    // Solid angle of the disc, sr: 2 pi (1 - cos(d/2)).
    double solidAngle() const;
};

struct ResolvedSky {
    Sky sky;
    V3d towardSun{0, 1, 0};      // what cie_general and perez skies are relative to
    int dayOfYear = 1;           // perez: of the sun's time
    double zenithLuminance = 0;  // cd/m^2
    double groundLuminance = 0;  // cd/m^2, below the horizon
    double horizontalIlluminance = 0;  // lx, of the sky alone on an open plane
    // perez: the hour's model (its clearness, brightness, Evd and Evn); nothing otherwise.
    std::optional<PerezSky> perez;

    // This sky's L / Lz.
    SkyDistribution distribution() const { return SkyDistribution(sky, towardSun, dayOfYear); }
    // Luminance (cd/m^2) seen looking along the unit world direction w: the sky above the
    // horizon, the ground below (at w.y == 0: the ground). With `relative`, this sky's
    // distribution() made once by a caller that evaluates many directions.
    double luminance(const V3d& w) const { return luminance(w, distribution()); }
    double luminance(const V3d& w, const SkyDistribution& relative) const;
    // Radiance per channel, W sr^-1 m^-2 (white).
    double radiance(const V3d& w) const { return luminance(w) / kLumensPerWatt; }
};

struct Daylight {
    std::optional<ResolvedSun> sun;  // a sun switched on
    std::optional<ResolvedSky> sky;
};

// The unit world direction toward the sun of a sun light: from its `direction`, or from its
// `time` at the scene's site (NREL SPA, refraction at 1010 hPa and 10 C). Throws SceneError for a
// time without a site (the reader already refuses that).
V3d sunDirection(const Scene& scene, const Light& sun);

// The daylight of a scene as renderers see it: its first sun that is switched on and its sky.
// Both absent for a scene without daylight. A perez sky's model gives the sun's illuminance and
// the sky's; so does the IES model of daylight_availability.h for a sky whose levels follow the
// sun's altitude (DaylightLevels::FollowAltitude), from where the scene's sun stands.
Daylight resolveDaylight(const Scene& scene);

// The scene SPEC.md's daylight factor is measured in: the sky made `cie_overcast` with the same
// quantity and ground reflectance (a scene without a sky gets one of 10,000 lx: the factor is a
// ratio and does not depend on it), the sun and every electric light removed, every emitting
// material black. Also returns Eh,sky (lx), the
// unobstructed horizontal illuminance of that sky alone, the factor's denominator.
struct DaylightFactorScene {
    Scene scene;
    double skyHorizontalIlluminance = 0;
};
DaylightFactorScene daylightFactorScene(const Scene& scene);

}  // namespace lucerna
