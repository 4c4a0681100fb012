// The lighting designer's keys of a scene file: maintenance factors, task areas with their
// activities and glare observers, the EN 12464-1 edition they are checked against, and the
// project's details for the report.

#include "core/scene/scene_parser.h"

#include "core/number_format.h"
#include "core/photometry/lighting_standards.h"
#include "core/scene/scene_resolve.h"

#include <cmath>

namespace lucerna {

MaintenanceFactor SceneParser::parseMaintenance(const Value& v, const std::string& place) const {
    MaintenanceFactor mf;
    if (v.type == Type::Number) {
        mf.value = numberIn(v, place, 0, true, 1, false);
        return mf;
    }
    if (v.type != Type::Object) fail(place, std::string("expected a number or an object, got ") + json::describe(v.type));
    checkKeys(v, place, {"llmf", "lsf", "lmf", "rsmf"});
    if (v.object.empty()) fail(place, "give at least one of llmf, lsf, lmf, rsmf");
    const auto factor = [&](const char* key, std::optional<double>& out) {
        if (const Value* f = v.find(key)) out = numberIn(*f, member(place, key), 0, true, 1, false);
    };
    factor("llmf", mf.lampLumenMaintenance);
    factor("lsf", mf.lampSurvival);
    factor("lmf", mf.luminaireMaintenance);
    factor("rsmf", mf.roomSurfaceMaintenance);
    return mf;
}

TaskArea SceneParser::parseTaskArea(const Value& v, const std::string& place, const std::vector<TaskArea>& earlier) const {
    checkKeys(v, place, {"name", "corner", "u", "v", "spacing", "activity", "surrounding_m", "background_m", "posture",
                         "observers"});
    TaskArea a;
    const std::string namePlace = member(place, "name");
    a.grid.name = text(required(v, place, "name"), namePlace);
    if (a.grid.name.empty()) fail(namePlace, "task area name is empty");
    if (a.grid.name.find('\0') != std::string::npos) fail(namePlace, "task area name contains a NUL character");
    for (const TaskArea& e : earlier)
        if (e.grid.name == a.grid.name) fail(namePlace, "another task area is already named " + quote(a.grid.name));
    a.grid.corner = vec3(required(v, place, "corner"), member(place, "corner"));
    a.grid.edgeU = direction(required(v, place, "u"), member(place, "u"));
    a.grid.edgeV = direction(required(v, place, "v"), member(place, "v"));
    const double cosine = a.grid.edgeU.dot(a.grid.edgeV) / (a.grid.edgeU.length() * a.grid.edgeV.length());
    if (std::abs(cosine) > 1e-6) fail(member(place, "v"), "u and v must be perpendicular");
    if (const Value* sp = v.find("spacing"))
        a.grid.spacingMeters = numberIn(*sp, member(place, "spacing"), 0, true, 1e6, false, " m");
    if (const Value* act = v.find("activity")) {
        a.activity = text(*act, member(place, "activity"));
        if (!findActivity(a.activity, StandardEdition::En12464_2021))  // either table
            fail(member(place, "activity"), "unknown activity " + quote(a.activity) +
                                                " (expected a reference number of EN 12464-1's table: `lucerna standards` lists them)");
    }
    // EN 12464-1's bands: the surrounding zone at least 0.5 m wide, the background area at least
    // 3 m around it (core/photometry/surrounding_zones.h).
    if (const Value* w = v.find("surrounding_m"))
        a.surroundingMeters = numberIn(*w, member(place, "surrounding_m"), 0.5, false, 1000, false, " m");
    if (const Value* w = v.find("background_m")) {
        a.backgroundMeters = numberIn(*w, member(place, "background_m"), 3, false, 1000, false, " m");
        if (!a.surroundingMeters)
            fail(member(place, "background_m"), "needs surrounding_m (the background area lies around the surrounding zone)");
    }
    // EN 12464-1:2021's Ez height: 1.2 m above the floor seated, 1.6 m standing.
    if (const Value* p = v.find("posture")) {
        const std::string posture = text(*p, member(place, "posture"));
        if (posture == "standing") a.standing = true;
        else if (posture != "seated")
            fail(member(place, "posture"), "unknown posture " + quote(posture) + " (expected \"seated\" or \"standing\")");
    }
    if (const Value* obs = v.find("observers")) {
        const std::string here = member(place, "observers");
        expectType(*obs, Type::Array, here);
        for (size_t i = 0; i < obs->array.size(); ++i) {
            const std::string o = item(here, i);
            checkKeys(obs->array[i], o, {"position", "view"});
            GlareObserver g;
            g.position = vec3(required(obs->array[i], o, "position"), member(o, "position"));
            g.view = direction(required(obs->array[i], o, "view"), member(o, "view"));
            a.observers.push_back(g);
        }
    }
    return a;
}

ProjectInfo SceneParser::parseProject(const Value& v, const std::string& place) const {
    checkKeys(v, place, {"name", "client", "designer", "notes"});
    ProjectInfo p;
    const auto field = [&](const char* key, std::string& out) {
        if (const Value* f = v.find(key)) out = text(*f, member(place, key));
    };
    field("name", p.name);
    field("client", p.client);
    field("designer", p.designer);
    field("notes", p.notes);
    return p;
}

StandardEdition SceneParser::parseLightingStandard(const Value& v, const std::string& place) const {
    const std::string name = text(v, place);
    const std::optional<StandardEdition> edition = standardEditionFromName(name);
    if (!edition)
        fail(place, "unknown edition " + quote(name) + " (expected " + quote(standardEditionName(StandardEdition::En12464_2021)) +
                        " or " + quote(standardEditionName(StandardEdition::En12464_2011)) + ")");
    return *edition;
}

EnergySettings SceneParser::parseEnergy(const Value& v, const std::string& place) const {
    checkKeys(v, place, {"building_type", "daytime_hours", "night_time_hours", "constant_illuminance_factor",
                         "occupancy_dependency_factor", "daylight_dependency_factor", "control_parasitic_watts",
                         "emergency_charging_watts", "emergency_charging_hours", "area_m2"});
    EnergySettings e;
    const std::string typePlace = member(place, "building_type");
    const std::string type = text(required(v, place, "building_type"), typePlace);
    const BuildingTypeHours* t = findBuildingType(type);
    if (!t) fail(typePlace, "unknown building type " + quote(type) + " (expected one of: " + buildingTypeKeys() + ")");
    e.buildingType = t->type;
    const auto value = [&](const char* key, std::optional<double>& out, double hi, const char* unit) {
        if (const Value* x = v.find(key)) out = numberIn(*x, member(place, key), 0, false, hi, false, unit);
    };
    value("daytime_hours", e.daytimeHours, kHoursPerYear, " h");
    value("night_time_hours", e.nightHours, kHoursPerYear, " h");
    value("constant_illuminance_factor", e.constantIlluminanceFactor, 1, "");
    value("occupancy_dependency_factor", e.occupancyFactor, 1, "");
    value("daylight_dependency_factor", e.daylightFactor, 1, "");
    value("control_parasitic_watts", e.controlParasiticWatts, 1e6, " W");
    value("emergency_charging_watts", e.emergencyChargingWatts, 1e6, " W");
    value("emergency_charging_hours", e.emergencyChargingHours, kHoursPerYear, " h");
    if (const Value* a = v.find("area_m2")) e.areaM2 = numberIn(*a, member(place, "area_m2"), 0, true, 1e9, false, " m2");
    if (const std::string problem = energySettingsProblem(e); !problem.empty()) fail(place, problem);
    return e;
}

}  // namespace lucerna
