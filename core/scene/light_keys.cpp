// The lights of a scene file: point, spot, directional, luminaire and sun (daylight_keys.cpp reads
// the sun's own keys), their photometric keys, groups and switches.

#include "core/scene/scene_parser.h"

#include "core/number_format.h"
#include "core/photometry/photometric_units.h"
#include "core/scene/scene_resolve.h"

namespace lucerna {

Light SceneParser::parseLight(const Value& v, const std::string& place) {
    expectType(v, Type::Object, place);
    Light l;
    const std::string type = text(required(v, place, "type"), member(place, "type"));
    const std::string what = "a " + type + " light";
    if (type == "point") {
        l.type = LightType::Point;
        checkKeys(v, place, {"name", "type", "position", "intensity", "lumens", "candela", "color", "temperature", "group", "on",
                             "maintenance_factor", "circuit_watts"}, what);
    } else if (type == "spot") {
        l.type = LightType::Spot;
        checkKeys(v, place, {"name", "type", "position", "direction", "intensity", "cone_angle", "falloff_start",
                             "lumens", "candela", "color", "temperature", "group", "on", "maintenance_factor",
                             "circuit_watts"}, what);
    } else if (type == "directional") {
        l.type = LightType::Directional;
        checkKeys(v, place, {"name", "type", "direction", "irradiance", "group", "on"}, what);
    } else if (type == "luminaire") {
        l.type = LightType::Luminaire;
        checkKeys(v, place, {"name", "type", "file", "position", "direction", "rotation", "lumens", "color",
                             "temperature", "group", "on", "maintenance_factor", "luminous_area", "circuit_watts"}, what);
        l.name = parseName(v, place);
        l.position = vec3(required(v, place, "position"), member(place, "position"));
        l.direction = direction(required(v, place, "direction"), member(place, "direction"));
        l.luminaire = parseLuminaire(v, place);
        parseGroupAndSwitch(v, place, l);
        if (const Value* mf = v.find("maintenance_factor"))
            l.maintenance = parseMaintenance(*mf, member(place, "maintenance_factor"));
        parseCircuitWatts(v, place, l);
        return l;
    } else if (type == "sun") {
        l.type = LightType::Sun;
        checkKeys(v, place, {"name", "type", "illuminance", "angular_diameter", "direction", "time", "color", "group", "on"},
                  what);
        l.name = parseName(v, place);
        l.sun = parseSun(v, place, l);
        parseGroupAndSwitch(v, place, l);
        return l;
    } else {
        fail(member(place, "type"), "unknown light type " + quote(type) +
                                        " (expected point, spot, directional, luminaire or sun)");
    }
    l.name = parseName(v, place);
    if (l.type != LightType::Directional) {
        l.position = vec3(required(v, place, "position"), member(place, "position"));
        l.photometric = parsePhotometric(v, place);
        if (!l.photometric) l.intensity = colour(required(v, place, "intensity"), member(place, "intensity"), false);
    }
    if (l.type != LightType::Point) l.direction = direction(required(v, place, "direction"), member(place, "direction"));
    if (l.type == LightType::Directional)
        l.irradiance = colour(required(v, place, "irradiance"), member(place, "irradiance"), false);
    if (l.type == LightType::Spot) {
        l.coneAngleDeg = numberIn(required(v, place, "cone_angle"), member(place, "cone_angle"), 0, true, 180, true, " degrees");
        if (const Value* f = v.find("falloff_start"))
            l.falloffStartDeg = numberIn(*f, member(place, "falloff_start"), 0, true, l.coneAngleDeg, false,
                                         " degrees (at most cone_angle)");
    }
    parseGroupAndSwitch(v, place, l);
    if (const Value* mf = v.find("maintenance_factor"))
        l.maintenance = parseMaintenance(*mf, member(place, "maintenance_factor"));
    parseCircuitWatts(v, place, l);
    if (l.photometric)
        l.intensity = photometricIntensity(*l.photometric, l.type == LightType::Spot
                                                               ? spotSolidAngle(l.coneAngleDeg, l.falloffStartDeg)
                                                               : pointSolidAngle());
    return l;
}

void SceneParser::parseGroupAndSwitch(const Value& v, const std::string& place, Light& l) const {
    if (const Value* g = v.find("group")) {
        const std::string here = member(place, "group");
        l.group = text(*g, here);
        if (l.group.empty()) fail(here, "group name is empty");
        if (l.group.find('\0') != std::string::npos) fail(here, "group name contains a NUL character");
    }
    if (const Value* on = v.find("on")) {
        expectType(*on, Type::Boolean, member(place, "on"));
        l.on = on->boolean;
    }
}

void SceneParser::parseCircuitWatts(const Value& v, const std::string& place, Light& l) const {
    if (const Value* w = v.find("circuit_watts"))
        l.circuitWatts = numberIn(*w, member(place, "circuit_watts"), 0, false, 1e6, false, " W");
}

LuminaireSpec SceneParser::parseLuminaire(const Value& v, const std::string& place) const {
    LuminaireSpec s;
    const std::string filePlace = member(place, "file");
    s.file = text(required(v, place, "file"), filePlace);
    if (s.file.empty()) fail(filePlace, "luminaire file path is empty");
    if (s.file.find('\0') != std::string::npos) fail(filePlace, "luminaire file path contains a NUL character");
    if (const Value* r = v.find("rotation")) s.rotationDeg = number(*r, member(place, "rotation"));
    if (const Value* lm = v.find("lumens")) {
        s.lumens = number(*lm, member(place, "lumens"));
        if (!(*s.lumens >= 0)) fail(member(place, "lumens"), "must be at least 0, got " + shortestNumber(*s.lumens));
    }
    parseLightColour(v, place, s.colour, s.temperatureK);
    if (const Value* area = v.find("luminous_area")) {
        const std::string here = member(place, "luminous_area");
        const Value& a = array(*area, here, 2, "numbers (width, length in metres)");
        s.luminousAreaM = V2d(numberIn(a.array[0], item(here, 0), 0, true, 1000, false, " m"),
                              numberIn(a.array[1], item(here, 1), 0, true, 1000, false, " m"));
    }
    return s;
}

std::optional<PhotometricSpec> SceneParser::parsePhotometric(const Value& v, const std::string& place) const {
    const Value* lumens = v.find("lumens");
    const Value* candela = v.find("candela");
    const Value* colourValue = v.find("color");
    const Value* temperature = v.find("temperature");
    const int given = (v.find("intensity") ? 1 : 0) + (lumens ? 1 : 0) + (candela ? 1 : 0);
    if (given > 1) fail(place, "give one of intensity, lumens and candela, not several");
    if (!lumens && !candela) {
        if (colourValue || temperature)
            fail(member(place, colourValue ? "color" : "temperature"), "only with lumens or candela");
        return std::nullopt;
    }
    PhotometricSpec p;
    p.quantity = lumens ? PhotometricSpec::Quantity::Lumens : PhotometricSpec::Quantity::Candela;
    const std::string key = lumens ? "lumens" : "candela";
    p.value = number(lumens ? *lumens : *candela, member(place, key));
    if (!(p.value >= 0)) fail(member(place, key), "must be at least 0, got " + shortestNumber(p.value));
    parseLightColour(v, place, p.colour, p.temperatureK);
    return p;
}

void SceneParser::parseLightColour(const Value& v, const std::string& place, std::optional<Rgbd>& rgb,
                                   std::optional<double>& kelvin) const {
    const Value* colourValue = v.find("color");
    const Value* temperature = v.find("temperature");
    if (colourValue && temperature) fail(place, "give color or temperature, not both");
    if (colourValue) {
        rgb = colour(*colourValue, member(place, "color"), false);
        if (!(luminance(*rgb) > 0)) fail(member(place, "color"), "must have a positive luminance");
    }
    if (temperature) kelvin = numberIn(*temperature, member(place, "temperature"), 1000, false, 40000, false, " kelvin");
}

}  // namespace lucerna
