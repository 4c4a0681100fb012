// Writing SPEC.md section 1. QJsonDocument is not used: it sorts object keys, which would reorder
// the materials map (kept in file order), and it lays out a mesh one number per line. This writer
// keeps the order of everything, writes numbers in their shortest form that reads back to the
// same double, and wraps long vertex and index lists.

#include "core/scene/json_string.h"
#include "core/number_format.h"
#include "core/scene/scene_io.h"

#include <QSaveFile>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lucerna {

namespace {

std::string num(double x) { return shortestNumber(x); }
std::string str(const std::string& s) { return jsonQuoted(s, JsonEscapes::Short); }

std::string vec(double x, double y, double z) { return "[" + num(x) + ", " + num(y) + ", " + num(z) + "]"; }
std::string vec(const V3d& v) { return vec(v.x, v.y, v.z); }
std::string rgb(const Rgbd& c) { return vec(c.x, c.y, c.z); }

// Appends "[a, b, c]" to `out`, breaking lines before an item that would pass column 100 and
// aligning continuation lines just inside the bracket.
void appendWrapped(std::string& out, const std::vector<std::string>& items) {
    const size_t lineStart = out.rfind('\n') + 1;  // npos + 1 == 0 on the first line
    const size_t indent = out.size() - lineStart + 1;
    size_t column = indent;
    out += '[';
    for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0) {
            out += ',';
            ++column;
            if (column + 1 + items[i].size() > 100) {
                out += '\n' + std::string(indent, ' ');
                column = indent;
            } else {
                out += ' ';
                ++column;
            }
        }
        out += items[i];
        column += items[i].size();
    }
    out += ']';
}

std::string material(const Material& m) {
    switch (m.type) {
    case MaterialType::Diffuse: return "{\"type\": \"diffuse\", \"albedo\": " + rgb(m.albedo) + "}";
    case MaterialType::Glossy:
        return "{\"type\": \"glossy\", \"albedo\": " + rgb(m.albedo) + ", \"specular\": " + rgb(m.specular) +
               ", \"roughness\": " + num(m.roughness) + "}";
    case MaterialType::Mirror: return "{\"type\": \"mirror\", \"reflectance\": " + rgb(m.reflectance) + "}";
    case MaterialType::Dielectric: return "{\"type\": \"dielectric\", \"ior\": " + num(m.ior) + "}";
    case MaterialType::Emitter: return "{\"type\": \"emitter\", \"radiance\": " + rgb(m.radiance) + "}";
    case MaterialType::Glazing: return "{\"type\": \"glazing\", \"transmittance\": " + rgb(m.transmittance) + "}";
    }
    return "{}";
}

void appendMesh(std::string& out, const MeshSource& mesh) {
    switch (mesh.kind) {
    case MeshSource::Kind::File: out += "{\"file\": " + str(mesh.file) + "}"; return;
    case MeshSource::Kind::Quad:
        out += "{\"quad\": [" + vec(mesh.quad[0]) + ", " + vec(mesh.quad[1]) + ", " + vec(mesh.quad[2]) + ", " +
               vec(mesh.quad[3]) + "]}";
        return;
    case MeshSource::Kind::Inline: {
        const size_t indent = out.size() - (out.rfind('\n') + 1) + 1;
        std::vector<std::string> items;
        for (const V3d& v : mesh.inlineMesh.vertices) items.push_back(vec(v));
        out += "{\"vertices\": ";
        appendWrapped(out, items);
        out += ",\n" + std::string(indent, ' ') + "\"triangles\": ";
        items.clear();
        for (const V3i& t : mesh.inlineMesh.triangles)
            items.push_back("[" + std::to_string(t.x) + ", " + std::to_string(t.y) + ", " + std::to_string(t.z) + "]");
        appendWrapped(out, items);
        out += "}";
        return;
    }
    }
}

std::string transform(const Transform& t) {
    if (t.isMatrix) {
        std::string m;
        for (int i = 0; i < 16; ++i) m += (i ? ", " : "") + num(t.matrix[i / 4][i % 4]);
        return "{\"matrix\": [" + m + "]}";
    }
    std::vector<std::string> parts;
    if (!t.uniformScale || t.scale != V3d(1, 1, 1)) {
        const bool uniform = t.uniformScale && t.scale.x == t.scale.y && t.scale.y == t.scale.z;
        parts.push_back("\"scale\": " + (uniform ? num(t.scale.x) : vec(t.scale)));
    }
    if (t.hasRotate)
        parts.push_back("\"rotate\": [" + num(t.rotateAxis.x) + ", " + num(t.rotateAxis.y) + ", " + num(t.rotateAxis.z) +
                        ", " + num(t.rotateDeg) + "]");
    if (t.translate != V3d(0, 0, 0)) parts.push_back("\"translate\": " + vec(t.translate));
    std::string out = "{";
    for (size_t i = 0; i < parts.size(); ++i) out += (i ? ", " : "") + parts[i];
    return out + "}";
}

// A point or spot light's output: its photometric keys while they still give its intensity (an
// edit of the intensity leaves them stale, and then the intensity is what counts).
std::string emission(const Light& l) {
    if (l.photometric) {
        const PhotometricSpec& p = *l.photometric;
        const double omega = l.type == LightType::Spot ? spotSolidAngle(l.coneAngleDeg, l.falloffStartDeg) : pointSolidAngle();
        const Rgbd i = photometricIntensity(p, omega);
        const double scale = std::max({std::abs(l.intensity.x), std::abs(l.intensity.y), std::abs(l.intensity.z), 1e-300});
        if (std::max({std::abs(i.x - l.intensity.x), std::abs(i.y - l.intensity.y), std::abs(i.z - l.intensity.z)}) <=
            1e-12 * scale) {
            std::string out = std::string(p.quantity == PhotometricSpec::Quantity::Lumens ? "\"lumens\": " : "\"candela\": ") +
                              num(p.value);
            if (p.colour) out += ", \"color\": " + rgb(*p.colour);
            if (p.temperatureK) out += ", \"temperature\": " + num(*p.temperatureK);
            return out;
        }
    }
    return "\"intensity\": " + rgb(l.intensity);
}

std::string maintenance(const MaintenanceFactor& mf) {
    if (mf.value) return num(*mf.value);
    std::string out;
    const auto factor = [&](const char* key, const std::optional<double>& f) {
        if (f) out += std::string(out.empty() ? "" : ", ") + "\"" + key + "\": " + num(*f);
    };
    factor("llmf", mf.lampLumenMaintenance);
    factor("lsf", mf.lampSurvival);
    factor("lmf", mf.luminaireMaintenance);
    factor("rsmf", mf.roomSurfaceMaintenance);
    return "{" + out + "}";
}

std::string light(const Light& l) {
    std::string out = "{\"name\": " + str(l.name) + ", \"type\": ";
    switch (l.type) {
    case LightType::Point:
        out += "\"point\", \"position\": " + vec(l.position) + ", " + emission(l);
        break;
    case LightType::Spot:
        out += "\"spot\", \"position\": " + vec(l.position) + ", \"direction\": " + vec(l.direction) +
               ", " + emission(l) + ", \"cone_angle\": " + num(l.coneAngleDeg);
        if (l.falloffStartDeg) out += ", \"falloff_start\": " + num(*l.falloffStartDeg);
        break;
    case LightType::Directional:
        out += "\"directional\", \"direction\": " + vec(l.direction) + ", \"irradiance\": " + rgb(l.irradiance);
        break;
    case LightType::Luminaire: {
        const LuminaireSpec s = l.luminaire.value_or(LuminaireSpec());
        out += "\"luminaire\", \"file\": " + str(s.file) + ", \"position\": " + vec(l.position) +
               ", \"direction\": " + vec(l.direction);
        if (s.rotationDeg) out += ", \"rotation\": " + num(*s.rotationDeg);
        if (s.lumens) out += ", \"lumens\": " + num(*s.lumens);
        if (s.colour) out += ", \"color\": " + rgb(*s.colour);
        if (s.temperatureK) out += ", \"temperature\": " + num(*s.temperatureK);
        if (s.luminousAreaM) out += ", \"luminous_area\": [" + num(s.luminousAreaM->x) + ", " + num(s.luminousAreaM->y) + "]";
        break;
    }
    case LightType::Sun: {
        const SunSpec s = l.sun.value_or(SunSpec());
        out += "\"sun\"";
        if (s.illuminanceGiven) out += ", \"illuminance\": " + num(s.illuminanceLux);
        if (s.angularDiameterGiven || s.angularDiameterDeg != SunSpec().angularDiameterDeg)
            out += ", \"angular_diameter\": " + num(s.angularDiameterDeg);
        if (s.time) out += ", \"time\": " + str(*s.time);
        else out += ", \"direction\": " + vec(l.direction);
        if (s.colour) out += ", \"color\": " + rgb(*s.colour);
        break;
    }
    }
    if (!l.group.empty()) out += ", \"group\": " + str(l.group);
    if (!l.on) out += ", \"on\": false";
    if (l.maintenance) out += ", \"maintenance_factor\": " + maintenance(*l.maintenance);
    if (l.circuitWatts) out += ", \"circuit_watts\": " + num(*l.circuitWatts);
    return out + "}";
}

std::string site(const Site& s) {
    std::string out = "{\"latitude\": " + num(s.latitudeDeg) + ", \"longitude\": " + num(s.longitudeDeg) +
                      ", \"utc_offset\": " + num(s.utcOffsetHours);
    if (s.northGiven || s.north != Site().north) out += ", \"north\": " + vec(s.north);
    if (s.medianDiffuseIlluminance) out += ", \"median_diffuse_illuminance\": " + num(*s.medianDiffuseIlluminance);
    return out + "}";
}

std::string sky(const Sky& s) {
    std::string out = "{\"model\": ";
    switch (s.model) {
    case SkyModelType::Uniform: out += "\"uniform\""; break;
    case SkyModelType::CieOvercast: out += "\"cie_overcast\""; break;
    case SkyModelType::CieGeneral: out += "\"cie_general\", \"cie_type\": " + std::to_string(s.cieType); break;
    case SkyModelType::Perez:
        out += "\"perez\", \"direct_normal_irradiance\": " + num(s.directNormalIrradiance) +
               ", \"diffuse_horizontal_irradiance\": " + num(s.diffuseHorizontalIrradiance);
        if (s.dewPointC) out += ", \"dew_point\": " + num(*s.dewPointC);
        break;
    }
    if (s.model == SkyModelType::Perez) {}
    else if (s.levels == DaylightLevels::FollowAltitude) out += ", \"daylight_levels\": \"altitude\"";
    else if (s.zenithLuminance) out += ", \"zenith_luminance\": " + num(*s.zenithLuminance);
    else out += ", \"horizontal_illuminance\": " + num(s.horizontalIlluminance.value_or(0.0));
    if (s.groundReflectanceGiven || s.groundReflectance != Sky().groundReflectance)
        out += ", \"ground_reflectance\": " + num(s.groundReflectance);
    return out + "}";
}

std::string taskArea(const TaskArea& a) {
    const CalculationGrid& g = a.grid;
    std::string out = "{\"name\": " + str(g.name) + ", \"corner\": " + vec(g.corner) + ", \"u\": " + vec(g.edgeU) +
                      ", \"v\": " + vec(g.edgeV);
    if (g.spacingMeters) out += ", \"spacing\": " + num(*g.spacingMeters);
    if (!a.activity.empty()) out += ", \"activity\": " + str(a.activity);
    if (a.surroundingMeters) out += ", \"surrounding_m\": " + num(*a.surroundingMeters);
    if (a.backgroundMeters) out += ", \"background_m\": " + num(*a.backgroundMeters);
    if (a.standing) out += ", \"posture\": \"standing\"";
    if (!a.observers.empty()) {
        out += ",\n     \"observers\": [";
        for (size_t i = 0; i < a.observers.size(); ++i)
            out += std::string(i ? ", " : "") + "{\"position\": " + vec(a.observers[i].position) +
                   ", \"view\": " + vec(a.observers[i].view) + "}";
        out += "]";
    }
    return out + "}";
}

std::string project(const ProjectInfo& p) {
    std::string out;
    const auto field = [&](const char* key, const std::string& value) {
        if (!value.empty()) out += std::string(out.empty() ? "" : ", ") + "\"" + key + "\": " + str(value);
    };
    field("name", p.name);
    field("client", p.client);
    field("designer", p.designer);
    field("notes", p.notes);
    return "{" + out + "}";
}

std::string energy(const EnergySettings& e) {
    std::string out = "{\"building_type\": " + str(buildingTypeHours(e.buildingType).key);
    const auto value = [&](const char* key, const std::optional<double>& x) {
        if (x) out += std::string(", \"") + key + "\": " + num(*x);
    };
    value("daytime_hours", e.daytimeHours);
    value("night_time_hours", e.nightHours);
    value("constant_illuminance_factor", e.constantIlluminanceFactor);
    value("occupancy_dependency_factor", e.occupancyFactor);
    value("daylight_dependency_factor", e.daylightFactor);
    value("control_parasitic_watts", e.controlParasiticWatts);
    value("emergency_charging_watts", e.emergencyChargingWatts);
    value("emergency_charging_hours", e.emergencyChargingHours);
    value("area_m2", e.areaM2);
    return out + "}";
}

// README, "Rooms": a parametric room's parameters, or a marked room's name alone.
std::string room(const Room& r) {
    std::string out = "{\"name\": " + str(r.name);
    if (!r.parametric()) return out + "}";
    out += ", \"outline\": [";
    for (size_t i = 0; i < r.outline.size(); ++i) out += (i ? ", [" : "[") + num(r.outline[i].x) + ", " + num(r.outline[i].y) + "]";
    out += "], \"floor_level\": " + num(r.floorLevel) + ", \"height\": " + num(r.height) +
           ",\n     \"materials\": {\"floor\": " + str(r.floorMaterial) + ", \"walls\": " + str(r.wallMaterial) +
           ", \"ceiling\": " + str(r.ceilingMaterial) + "}";
    if (!r.openings.empty()) {
        out += ",\n     \"openings\": [";
        for (size_t i = 0; i < r.openings.size(); ++i) {
            const RoomOpening& o = r.openings[i];
            out += std::string(i ? ",\n                   " : "") + "{\"type\": \"" +
                   (o.type == OpeningType::Window ? "window" : o.type == OpeningType::Door ? "door" : "opening") +
                   "\", \"wall\": " + std::to_string(o.wall) + ", \"offset\": " + num(o.offset);
            if (o.type != OpeningType::Door) out += ", \"sill\": " + num(o.sill);
            out += ", \"width\": " + num(o.width) + ", \"height\": " + num(o.height);
            if (o.type == OpeningType::Window) out += ", \"glazing\": " + str(o.glazing);
            out += "}";
        }
        out += "]";
    }
    return out + "}";
}

}  // namespace

std::string saveSceneToString(const Scene& scene) {
    std::string out = "{\n  \"lucerna\": 1,\n";
    if (scene.metersPerUnitGiven || scene.metersPerUnit != 1.0)
        out += "  \"meters_per_unit\": " + num(scene.metersPerUnit) + ",\n";

    const Camera& c = scene.camera;
    out += "  \"camera\": {\"position\": " + vec(c.position) + ", \"target\": " + vec(c.target) + ", \"up\": " +
           vec(c.up) + ",\n             \"fov_y\": " + num(c.fovYDeg) + ", \"resolution\": [" +
           std::to_string(c.width) + ", " + std::to_string(c.height) + "]},\n";

    out += "  \"materials\": {";
    for (size_t i = 0; i < scene.materials.size(); ++i)
        out += (i ? ",\n    " : "\n    ") + str(scene.materials[i].name) + ": " + material(scene.materials[i]);
    out += scene.materials.empty() ? "},\n" : "\n  },\n";

    out += "  \"objects\": [";
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        out += (i ? ",\n    " : "\n    ");
        out += "{\"name\": " + str(o.name) + ", \"material\": " + str(o.material);
        if (!o.room.empty()) out += ", \"room\": " + str(o.room);
        if (o.portal) out += ", \"portal\": true";
        out += ",\n     \"mesh\": ";
        appendMesh(out, o.mesh);
        if (o.transform) out += ",\n     \"transform\": " + transform(*o.transform);
        out += "}";
    }
    out += scene.objects.empty() ? "]" : "\n  ]";

    if (!scene.lights.empty()) {
        out += ",\n  \"lights\": [";
        for (size_t i = 0; i < scene.lights.size(); ++i) out += (i ? ",\n    " : "\n    ") + light(scene.lights[i]);
        out += "\n  ]";
    }
    if (scene.site) out += ",\n  \"site\": " + site(*scene.site);
    if (scene.sky) out += ",\n  \"sky\": " + sky(*scene.sky);
    if (scene.maintenance) out += ",\n  \"maintenance_factor\": " + maintenance(*scene.maintenance);
    if (scene.lightingStandard) out += ",\n  \"lighting_standard\": " + str(standardEditionName(*scene.lightingStandard));
    if (!scene.taskAreas.empty()) {
        out += ",\n  \"task_areas\": [";
        for (size_t i = 0; i < scene.taskAreas.size(); ++i) out += (i ? ",\n    " : "\n    ") + taskArea(scene.taskAreas[i]);
        out += "\n  ]";
    }
    if (scene.project) out += ",\n  \"project\": " + project(*scene.project);
    if (scene.energy) out += ",\n  \"energy\": " + energy(*scene.energy);
    if (!scene.rooms.empty()) {
        out += ",\n  \"rooms\": [";
        for (size_t i = 0; i < scene.rooms.size(); ++i) out += (i ? ",\n    " : "\n    ") + room(scene.rooms[i]);
        out += "\n  ]";
    }
    return out + "\n}\n";
}

void saveScene(const Scene& scene, const std::string& path) {
    const std::string text = saveSceneToString(scene);
    // QSaveFile writes to a temporary file in the same folder and renames it over `path` on
    // commit; on any failure the temporary is removed and `path` keeps its old contents.
    QSaveFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::WriteOnly))
        throw std::runtime_error(path + ": cannot write the scene: " + file.errorString().toStdString());
    if (file.write(text.data(), qint64(text.size())) != qint64(text.size()) || !file.commit())
        throw std::runtime_error(path + ": cannot write the scene: " + file.errorString().toStdString());
}

}  // namespace lucerna
