// Daylight in a scene file (SPEC.md section 5): the sun's keys, the site, the sky, and the rules
// that span them.

#include "core/scene/scene_parser.h"

#include "core/daylight/solar_position.h"
#include "core/number_format.h"
#include "core/scene/scene_resolve.h"

#include <cmath>

namespace lucerna {

SunSpec SceneParser::parseSun(const Value& v, const std::string& place, Light& l) const {
    SunSpec s;
    // A perez sky gives the sun's illuminance; checkDaylight() judges its absence.
    const std::string lux = member(place, "illuminance");
    if (const Value* e = v.find("illuminance")) {
        s.illuminanceLux = number(*e, lux);
        if (!(s.illuminanceLux >= 0)) fail(lux, "must be at least 0, got " + shortestNumber(s.illuminanceLux));
    } else {
        s.illuminanceGiven = false;
    }
    if (const Value* d = v.find("angular_diameter")) {
        s.angularDiameterDeg = numberIn(*d, member(place, "angular_diameter"), 0, false, 5, false, " degrees");
        s.angularDiameterGiven = true;
    }
    const Value* direction = v.find("direction");
    const Value* time = v.find("time");
    if (direction && time) fail(place, "give direction or time, not both");
    if (!direction && !time) fail(place, "a sun needs \"direction\" or \"time\"");
    if (direction) l.direction = this->direction(*direction, member(place, "direction"));
    if (time) {
        const std::string here = member(place, "time");
        s.time = text(*time, here);
        if (!parseLocalTime(*s.time))
            fail(here, "expected a local time \"YYYY-MM-DDTHH:MM\", got " + quote(*s.time));
    }
    if (const Value* c = v.find("color")) {
        s.colour = colour(*c, member(place, "color"), false);
        if (!(luminance(*s.colour) > 0)) fail(member(place, "color"), "must have a positive luminance");
    }
    return s;
}

Site SceneParser::parseSite(const Value& v, const std::string& place) const {
    checkKeys(v, place, {"latitude", "longitude", "utc_offset", "north", "median_diffuse_illuminance"});
    Site s;
    s.latitudeDeg = numberIn(required(v, place, "latitude"), member(place, "latitude"), -90, false, 90, false, " degrees");
    s.longitudeDeg = numberIn(required(v, place, "longitude"), member(place, "longitude"), -180, false, 180, false, " degrees");
    s.utcOffsetHours = numberIn(required(v, place, "utc_offset"), member(place, "utc_offset"), -14, false, 14, false, " hours");
    if (const Value* n = v.find("north")) {
        const std::string here = member(place, "north");
        s.north = direction(*n, here);
        if (s.north.y != 0) fail(item(here, 1), "north is horizontal: its y must be 0, got " + shortestNumber(s.north.y));
        s.northGiven = true;
    }
    if (const Value* e = v.find("median_diffuse_illuminance"))
        s.medianDiffuseIlluminance =
            numberIn(*e, member(place, "median_diffuse_illuminance"), 0, true, 200000, false, " lx");
    return s;
}

Sky SceneParser::parseSky(const Value& v, const std::string& place) const {
    Sky s;
    const std::string modelPlace = member(place, "model");
    const std::string model = text(required(v, place, "model"), modelPlace);
    if (model == "uniform") s.model = SkyModelType::Uniform;
    else if (model == "cie_overcast") s.model = SkyModelType::CieOvercast;
    else if (model == "cie_general") s.model = SkyModelType::CieGeneral;
    else if (model == "perez") return parsePerezSky(v, place);
    else fail(modelPlace, "unknown sky model " + quote(model) + " (expected uniform, cie_overcast, cie_general or perez)");
    checkKeys(v, place, {"model", "cie_type", "zenith_luminance", "horizontal_illuminance", "ground_reflectance", "daylight_levels"});
    const Value* type = v.find("cie_type");
    if (s.model == SkyModelType::CieGeneral) {
        const std::string here = member(place, "cie_type");
        const double t = integer(required(v, place, "cie_type"), here);
        if (t < 1 || t > 15) fail(here, "must be from 1 to 15, got " + shortestNumber(t));
        s.cieType = int(t);
    } else if (type) {
        fail(member(place, "cie_type"), "only for the cie_general model");
    }
    if (const Value* g = v.find("ground_reflectance")) {
        s.groundReflectance = numberIn(*g, member(place, "ground_reflectance"), 0, false, 1, false);
        s.groundReflectanceGiven = true;
    }
    const Value* lz = v.find("zenith_luminance");
    const Value* eh = v.find("horizontal_illuminance");
    // An addition (README, "Daylight levels"): "altitude" computes the sky's quantity and the
    // sun's illuminance from the sun's altitude; "fixed" (the default) takes the file's numbers.
    if (const Value* levels = v.find("daylight_levels")) {
        const std::string here = member(place, "daylight_levels");
        const std::string name = text(*levels, here);
        if (name == "altitude") s.levels = DaylightLevels::FollowAltitude;
        else if (name != "fixed") fail(here, "expected \"altitude\" or \"fixed\", got " + quote(name));
    }
    if (s.levels == DaylightLevels::FollowAltitude) {
        if (lz || eh)
            fail(member(place, lz ? "zenith_luminance" : "horizontal_illuminance"),
                 "with \"daylight_levels\": \"altitude\" the sun's altitude gives the sky's level: give no quantity");
        return s;
    }
    if ((lz != nullptr) == (eh != nullptr))
        fail(place, "give exactly one of zenith_luminance and horizontal_illuminance");
    const std::string quantityPlace = member(place, lz ? "zenith_luminance" : "horizontal_illuminance");
    const double quantity = number(lz ? *lz : *eh, quantityPlace);
    if (!(quantity >= 0) || !std::isfinite(quantity))
        fail(quantityPlace, "must be a finite number at least 0, got " + shortestNumber(quantity));
    (lz ? s.zenithLuminance : s.horizontalIlluminance) = quantity;
    return s;
}

Sky SceneParser::parsePerezSky(const Value& v, const std::string& place) const {
    checkKeys(v, place, {"model", "direct_normal_irradiance", "diffuse_horizontal_irradiance", "dew_point", "ground_reflectance"});
    Sky s;
    s.model = SkyModelType::Perez;
    const auto irradiance = [&](const char* key) {
        const std::string here = member(place, key);
        const double value = number(required(v, place, key), here);
        if (!(value >= 0) || !std::isfinite(value))
            fail(here, "must be a finite number at least 0 (W/m^2), got " + shortestNumber(value));
        return value;
    };
    s.directNormalIrradiance = irradiance("direct_normal_irradiance");
    s.diffuseHorizontalIrradiance = irradiance("diffuse_horizontal_irradiance");
    if (const Value* d = v.find("dew_point")) s.dewPointC = numberIn(*d, member(place, "dew_point"), -90, false, 60, false, " C");
    if (const Value* g = v.find("ground_reflectance")) {
        s.groundReflectance = numberIn(*g, member(place, "ground_reflectance"), 0, false, 1, false);
        s.groundReflectanceGiven = true;
    }
    return s;
}

void SceneParser::checkDaylight(const Scene& scene) const {
    int suns = 0;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        if (l.type != LightType::Sun) continue;
        if (++suns > 1) fail(item("lights", i), "a scene has at most one sun");
        if (l.sun && l.sun->time && !scene.site)
            fail(member(item("lights", i), "time"), "a sun placed by time needs the scene's \"site\"");
        const bool perez = scene.sky && scene.sky->model == SkyModelType::Perez;
        const bool altitude = scene.sky && scene.sky->levels == DaylightLevels::FollowAltitude;
        if (l.sun && perez && (l.sun->illuminanceGiven || !l.sun->time))
            fail(item("lights", i), "beside a perez sky the sun has a \"time\" and no \"illuminance\" (the sky's model gives it)");
        if (l.sun && altitude && l.sun->illuminanceGiven)
            fail(member(item("lights", i), "illuminance"),
                 "beside a sky with \"daylight_levels\": \"altitude\" the sun has no \"illuminance\" (its altitude gives it)");
        if (l.sun && !perez && !altitude && !l.sun->illuminanceGiven)
            fail(member(item("lights", i), "illuminance"), "required key is missing");
    }
    if (scene.sky && scene.sky->levels == DaylightLevels::FollowAltitude && suns == 0)
        fail("sky.daylight_levels", "levels that follow the sun's altitude need a light of type \"sun\"");
    if (scene.sky && scene.sky->model == SkyModelType::Perez && suns == 0)
        fail("sky.model", "a perez sky needs a light of type \"sun\" with a \"time\"");
    if (scene.sky && scene.sky->model == SkyModelType::CieGeneral && suns == 0)
        fail("sky.model", "a cie_general sky needs a light of type \"sun\"");
}

}  // namespace lucerna
