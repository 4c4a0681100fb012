#include "core/daylight/daylight.h"

#include "core/scene/scene_io.h"
#include "core/daylight/daylight_availability.h"
#include "core/daylight/sky_model.h"
#include "core/daylight/solar_position.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {
constexpr double kPiD = std::numbers::pi;
}

Rgbd ResolvedSun::irradiance() const {
    if (!aboveHorizon) return Rgbd(0, 0, 0);
    return colour * (illuminanceLux / kLumensPerWatt);
}

double ResolvedSun::solidAngle() const { return 2 * kPiD * (1 - std::cos(halfAngleRad)); }

Rgbd ResolvedSun::radiance() const {
    if (!aboveHorizon || !(halfAngleRad > 0)) return Rgbd(0, 0, 0);
    const double s = std::sin(halfAngleRad);
    return colour * (illuminanceLux / (kLumensPerWatt * kPiD * s * s));
}

double ResolvedSky::luminance(const V3d& w, const SkyDistribution& relative) const {
    return w.y > 0 ? zenithLuminance * relative(w) : groundLuminance;
}

namespace {

// SPEC.md section 6: the hour's model gives the sky's luminance and the sun's illuminance.
void resolvePerez(ResolvedSky& s, std::optional<ResolvedSun>& sun) {
    const PerezInputs in{s.sky.directNormalIrradiance, s.sky.diffuseHorizontalIrradiance, s.sky.dewPointC.value_or(11.0),
                         s.dayOfYear, s.towardSun};
    s.perez.emplace(in);
    s.horizontalIlluminance = s.perez->diffuseIlluminance();
    s.zenithLuminance = s.perez->luminanceScale() / s.distribution().normalisation();
    if (sun) sun->illuminanceLux = s.perez->directNormalIlluminance();
}

// A sky whose levels follow the sun's altitude (DaylightLevels::FollowAltitude): the IES model
// gives the sky's horizontal illuminance and the sun's direct normal illuminance, from where the
// sun stands (switched on or not) and its date when it has one.
void resolveAltitudeLevels(ResolvedSky& s, std::optional<ResolvedSun>& sun, std::optional<int> day) {
    const double altitudeDeg = std::asin(std::clamp(s.towardSun.y, -1.0, 1.0)) * 180.0 / kPiD;
    const SkyCondition condition = skyCondition(s.sky);
    s.horizontalIlluminance = skyHorizontalIlluminance(condition, altitudeDeg);
    const double relativeEh = relativeHorizontalIlluminance(s.sky, s.towardSun);
    s.zenithLuminance = relativeEh > 0 ? s.horizontalIlluminance / relativeEh : 0.0;
    if (sun) sun->illuminanceLux = sunDirectNormalIlluminance(condition, altitudeDeg, day);
}

}  // namespace

V3d sunDirection(const Scene& scene, const Light& sun) {
    if (!sun.sun || !sun.sun->time) return (-sun.direction).normalized();
    if (!scene.site) throw SceneError("sun " + sun.name + ": a sun placed by time needs the scene's site");
    const auto time = parseLocalTime(*sun.sun->time);
    if (!time) throw SceneError("sun " + sun.name + ": bad local time " + *sun.sun->time);
    SolarPositionInput in;
    in.time = *time;
    in.utcOffsetHours = scene.site->utcOffsetHours;
    in.latitudeDeg = scene.site->latitudeDeg;
    in.longitudeDeg = scene.site->longitudeDeg;
    return directionTowardSun(solarPosition(in), scene.site->north);
}

Daylight resolveDaylight(const Scene& scene) {
    Daylight d;
    for (const Light& l : scene.lights) {
        if (l.type != LightType::Sun || !l.on || !l.sun) continue;
        ResolvedSun s;
        s.towardSun = sunDirection(scene, l);
        s.illuminanceLux = l.sun->illuminanceLux;
        s.halfAngleRad = 0.5 * l.sun->angularDiameterDeg * kPiD / 180.0;
        if (l.sun->colour) s.colour = *l.sun->colour / luminance(*l.sun->colour);
        s.aboveHorizon = s.towardSun.y > 0;
        d.sun = s;
        break;
    }
    if (scene.sky) {
        ResolvedSky s;
        s.sky = *scene.sky;
        // A cie_general or perez sky without a sun switched on keeps the sun's place (the reader
        // insists on a sun); other skies do not read it.
        s.towardSun = d.sun ? d.sun->towardSun : V3d(0, 1, 0);
        std::optional<int> day;  // of the sun's time, when it has one
        for (const Light& l : scene.lights) {
            if (l.type != LightType::Sun) continue;
            if (!d.sun) s.towardSun = sunDirection(scene, l);
            if (l.sun && l.sun->time)
                if (const auto t = parseLocalTime(*l.sun->time)) {
                    day = dayOfYear(t->year, t->month, t->day);
                    s.dayOfYear = *day;
                }
        }
        if (s.sky.model == SkyModelType::Perez) {
            resolvePerez(s, d.sun);
        } else if (s.sky.levels == DaylightLevels::FollowAltitude) {
            resolveAltitudeLevels(s, d.sun, day);
        } else {
            // Eh / Lz once: it gives Lz from a horizontal illuminance and the ground's light.
            const double relativeEh = relativeHorizontalIlluminance(s.sky, s.towardSun);
            s.zenithLuminance = s.sky.zenithLuminance.value_or(relativeEh > 0 ? s.sky.horizontalIlluminance.value_or(0.0) / relativeEh : 0.0);
            s.horizontalIlluminance = s.zenithLuminance * relativeEh;
        }
        double eh = s.horizontalIlluminance;
        if (d.sun && d.sun->aboveHorizon) eh += d.sun->illuminanceLux * d.sun->towardSun.y;
        s.groundLuminance = s.sky.groundReflectance * eh / kPiD;
        d.sky = s;
    }
    return d;
}

DaylightFactorScene daylightFactorScene(const Scene& scene) {
    DaylightFactorScene out{scene, 0.0};
    Scene& s = out.scene;
    Sky sky;
    if (scene.sky && scene.sky->levels == DaylightLevels::Fixed) {
        sky.zenithLuminance = scene.sky->zenithLuminance;
        sky.horizontalIlluminance = scene.sky->horizontalIlluminance;
        sky.groundReflectance = scene.sky->groundReflectance;
        sky.groundReflectanceGiven = scene.sky->groundReflectanceGiven;
    } else {
        // Any quantity gives the same ratio (a sky whose levels follow the sun has none).
        sky.horizontalIlluminance = 10000.0;
        if (scene.sky) sky.groundReflectance = scene.sky->groundReflectance, sky.groundReflectanceGiven = scene.sky->groundReflectanceGiven;
    }
    sky.model = SkyModelType::CieOvercast;
    sky.cieType = 0;
    s.sky = sky;
    s.lights.clear();
    for (Material& m : s.materials)
        if (m.type == MaterialType::Emitter) m.radiance = Rgbd(0, 0, 0);
    out.skyHorizontalIlluminance = zenithLuminance(sky, V3d(0, 1, 0)) * relativeHorizontalIlluminance(sky, V3d(0, 1, 0));
    return out;
}

}  // namespace lucerna
