// Reading SPEC.md section 1: JSON text -> validated Scene -> world-space meshes. Every rule of the
// contract is checked here, and every violation becomes one SceneError line
// "<file>: <JSON path>: <problem>".

#include "core/scene/json_reader.h"
#include "core/scene/json_string.h"
#include "core/photometry/lighting_standards.h"
#include "core/number_format.h"
#include "core/regular_file.h"
#include "core/scene/scene_io.h"
#include "core/scene/scene_resolve.h"
#include "core/daylight/solar_position.h"

#include <QFile>
#include <QFileInfo>

#include <unordered_map>

namespace lucerna {

namespace {

using json::Type;
using json::Value;

inline constexpr int kMaxResolution = 16384;
inline constexpr const char* kTopLevel = "top level";


bool isPlainKey(const std::string& key) {
    if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
    for (unsigned char c : key)
        if (!(std::isalnum(c) || c == '_' || c == '-')) return false;
    return true;
}

// JSON paths: camera.fov_y, objects[2].mesh.vertices[5][1], materials["my glass"].ior.
std::string member(const std::string& parent, const std::string& key) {
    if (!isPlainKey(key)) return (parent == kTopLevel ? std::string() : parent) + "[" + quote(key) + "]";
    return parent == kTopLevel ? key : parent + "." + key;
}

class SceneParser {
public:
    explicit SceneParser(const std::string& file) : file_(file) {}

    Scene parse(const Value& root) {
        Scene scene;
        const std::string top = kTopLevel;
        expectType(root, Type::Object, top);
        // The version first: a newer file may well have keys this reader does not know.
        const Value& version = required(root, top, "lucerna");
        const double v = integer(version, "lucerna");
        if (v != 1) fail("lucerna", "unsupported format version " + shortestNumber(v) + " (this reader reads version 1)");
        checkKeys(root, top, {"lucerna", "meters_per_unit", "camera", "materials", "objects", "lights", "site", "sky",
                             "maintenance_factor", "task_areas", "project"});
        scene.version = 1;
        if (const Value* mpu = root.find("meters_per_unit")) {
            scene.metersPerUnit = number(*mpu, "meters_per_unit");
            if (!(scene.metersPerUnit > 0))
                fail("meters_per_unit", "must be positive, got " + shortestNumber(scene.metersPerUnit));
            scene.metersPerUnitGiven = true;
        }
        scene.camera = parseCamera(required(root, top, "camera"), "camera");
        parseMaterials(required(root, top, "materials"), "materials", scene);
        const Value& objects = required(root, top, "objects");
        expectType(objects, Type::Array, "objects");
        for (size_t i = 0; i < objects.array.size(); ++i)
            scene.objects.push_back(parseObject(objects.array[i], item("objects", i), scene));
        if (const Value* lights = root.find("lights")) {
            expectType(*lights, Type::Array, "lights");
            for (size_t i = 0; i < lights->array.size(); ++i)
                scene.lights.push_back(parseLight(lights->array[i], item("lights", i)));
        }
        if (const Value* site = root.find("site")) scene.site = parseSite(*site, "site");
        if (const Value* sky = root.find("sky")) scene.sky = parseSky(*sky, "sky");
        checkDaylight(scene);
        if (const Value* mf = root.find("maintenance_factor")) scene.maintenance = parseMaintenance(*mf, "maintenance_factor");
        if (const Value* areas = root.find("task_areas")) {
            expectType(*areas, Type::Array, "task_areas");
            for (size_t i = 0; i < areas->array.size(); ++i)
                scene.taskAreas.push_back(parseTaskArea(areas->array[i], item("task_areas", i), scene.taskAreas));
        }
        if (const Value* project = root.find("project")) scene.project = parseProject(*project, "project");
        return scene;
    }

private:
    [[noreturn]] void fail(const std::string& place, const std::string& problem) const {
        throw SceneError(file_ + ": " + place + ": " + problem);
    }

    void expectType(const Value& v, Type type, const std::string& place) const {
        if (v.type != type)
            fail(place, std::string("expected ") + json::describe(type) + ", got " + json::describe(v.type));
    }

    // `v` is an object whose keys are all among `allowed` (listed in the message otherwise).
    void checkKeys(const Value& v, const std::string& place, std::initializer_list<std::string_view> allowed,
                   const std::string& what = {}) const {
        expectType(v, Type::Object, place);
        for (const json::Member& m : v.object) {
            bool known = false;
            for (std::string_view k : allowed) known = known || m.key == k;
            if (known) continue;
            std::string list;
            for (std::string_view k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
            fail(member(place, m.key), "unknown key" + (what.empty() ? std::string() : " for " + what) +
                                           " (expected one of: " + list + ")");
        }
    }

    const Value& required(const Value& object, const std::string& place, const std::string& key) const {
        if (const Value* v = object.find(key)) return *v;
        fail(member(place, key), "required key is missing");
    }

    double number(const Value& v, const std::string& place) const {
        expectType(v, Type::Number, place);
        return v.number;
    }

    // SPEC.md: "indices and resolutions are integers". As in JSON Schema, a number with no
    // fractional part (2, 2.0, 2e0) is an integer.
    double integer(const Value& v, const std::string& place) const {
        const double x = number(v, place);
        if (x != std::floor(x)) fail(place, "expected an integer, got " + shortestNumber(x));
        return x;
    }

    double numberIn(const Value& v, const std::string& place, double lo, bool loOpen, double hi, bool hiOpen,
                    const std::string& unit = {}) const {
        const double x = number(v, place);
        const bool ok = (loOpen ? x > lo : x >= lo) && (hiOpen ? x < hi : x <= hi);
        if (!ok)
            fail(place, "must be in " + std::string(loOpen ? "(" : "[") + shortestNumber(lo) + ", " + shortestNumber(hi) +
                            (hiOpen ? ")" : "]") + unit + ", got " + shortestNumber(x));
        return x;
    }

    std::string text(const Value& v, const std::string& place) const {
        expectType(v, Type::String, place);
        return v.string;
    }

    const Value& array(const Value& v, const std::string& place, size_t size, const char* what) const {
        expectType(v, Type::Array, place);
        if (v.array.size() != size)
            fail(place, "expected an array of " + std::to_string(size) + " " + what + ", got " +
                            std::to_string(v.array.size()) + " element" + (v.array.size() == 1 ? "" : "s"));
        return v;
    }

    V3d vec3(const Value& v, const std::string& place) const {
        const Value& a = array(v, place, 3, "numbers");
        return V3d(number(a.array[0], item(place, 0)), number(a.array[1], item(place, 1)),
                   number(a.array[2], item(place, 2)));
    }

    V3d direction(const Value& v, const std::string& place) const {
        const V3d d = vec3(v, place);
        if (d == V3d(0, 0, 0)) fail(place, "direction must be non-zero");
        return d;
    }

    // Albedo-like colours are fractions in [0, 1]; radiometric ones are at least 0.
    Rgbd colour(const Value& v, const std::string& place, bool fraction) const {
        const Value& a = array(v, place, 3, "numbers (R, G, B)");
        double c[3];
        for (size_t i = 0; i < 3; ++i) {
            c[i] = fraction ? numberIn(a.array[i], item(place, i), 0, false, 1, false)
                            : number(a.array[i], item(place, i));
            if (!fraction && c[i] < 0) fail(item(place, i), "must be at least 0, got " + shortestNumber(c[i]));
        }
        return Rgbd(c[0], c[1], c[2]);
    }

    Camera parseCamera(const Value& v, const std::string& place) const {
        checkKeys(v, place, {"position", "target", "up", "fov_y", "resolution"});
        Camera c;
        c.position = vec3(required(v, place, "position"), member(place, "position"));
        c.target = vec3(required(v, place, "target"), member(place, "target"));
        if (const Value* up = v.find("up")) c.up = direction(*up, member(place, "up"));
        c.fovYDeg = numberIn(required(v, place, "fov_y"), member(place, "fov_y"), 0, true, 180, true, " degrees");
        const std::string resPlace = member(place, "resolution");
        const Value& res = array(required(v, place, "resolution"), resPlace, 2, "integers (width, height)");
        int size[2];
        for (size_t i = 0; i < 2; ++i) {
            const double n = integer(res.array[i], item(resPlace, i));
            if (n < 1 || n > kMaxResolution)
                fail(item(resPlace, i), "must be from 1 to " + std::to_string(kMaxResolution) + ", got " + shortestNumber(n));
            size[i] = int(n);
        }
        c.width = size[0];
        c.height = size[1];
        if (c.target == c.position) fail(member(place, "target"), "target equals position, so there is no view direction");
        const V3d view = c.target - c.position;
        if (!std::isfinite(view.length())) fail(member(place, "target"), "target is too far from position");
        const V3d f = view.normalized();
        // Parallel within rounding: cross(f, up) would give no usable right vector.
        if (f.cross(c.up.normalized()).length() < 1e-9) fail(member(place, "up"), "up is parallel to the view direction");
        return c;
    }

    void parseMaterials(const Value& v, const std::string& place, Scene& scene) const {
        expectType(v, Type::Object, place);
        for (const json::Member& m : v.object) {
            const std::string here = member(place, m.key);
            expectType(m.value, Type::Object, here);
            Material mat;
            mat.name = m.key;
            const std::string type = text(required(m.value, here, "type"), member(here, "type"));
            const std::string what = "a " + type + " material";
            if (type == "diffuse") {
                mat.type = MaterialType::Diffuse;
                checkKeys(m.value, here, {"type", "albedo"}, what);
                mat.albedo = colour(required(m.value, here, "albedo"), member(here, "albedo"), true);
            } else if (type == "glossy") {
                mat.type = MaterialType::Glossy;
                checkKeys(m.value, here, {"type", "albedo", "specular", "roughness"}, what);
                mat.albedo = colour(required(m.value, here, "albedo"), member(here, "albedo"), true);
                mat.specular = colour(required(m.value, here, "specular"), member(here, "specular"), true);
                mat.roughness = numberIn(required(m.value, here, "roughness"), member(here, "roughness"), 0, true, 1, false);
            } else if (type == "mirror") {
                mat.type = MaterialType::Mirror;
                checkKeys(m.value, here, {"type", "reflectance"}, what);
                mat.reflectance = colour(required(m.value, here, "reflectance"), member(here, "reflectance"), true);
            } else if (type == "dielectric") {
                mat.type = MaterialType::Dielectric;
                checkKeys(m.value, here, {"type", "ior"}, what);
                mat.ior = number(required(m.value, here, "ior"), member(here, "ior"));
                if (!(mat.ior > 0)) fail(member(here, "ior"), "must be positive, got " + shortestNumber(mat.ior));
            } else if (type == "glazing") {
                mat.type = MaterialType::Glazing;
                checkKeys(m.value, here, {"type", "transmittance"}, what);
                mat.transmittance = colour(required(m.value, here, "transmittance"), member(here, "transmittance"), true);
            } else if (type == "emitter") {
                mat.type = MaterialType::Emitter;
                checkKeys(m.value, here, {"type", "radiance"}, what);
                mat.radiance = colour(required(m.value, here, "radiance"), member(here, "radiance"), false);
            } else {
                fail(member(here, "type"), "unknown material type " + quote(type) +
                                               " (expected diffuse, glossy, mirror, dielectric, emitter or glazing)");
            }
            scene.materials.push_back(std::move(mat));
        }
    }

    std::string parseName(const Value& v, const std::string& place) {
        const std::string here = member(place, "name");
        std::string name = text(required(v, place, "name"), here);
        const auto [it, fresh] = names_.emplace(name, here);
        if (!fresh) fail(here, "name " + quote(name) + " is already used by " + it->second);
        return name;
    }

    Object parseObject(const Value& v, const std::string& place, const Scene& scene) {
        checkKeys(v, place, {"name", "material", "mesh", "transform"});
        Object o;
        o.name = parseName(v, place);
        o.material = text(required(v, place, "material"), member(place, "material"));
        if (scene.materialIndex(o.material) < 0)
            fail(member(place, "material"), "unknown material " + quote(o.material));
        o.mesh = parseMesh(required(v, place, "mesh"), member(place, "mesh"));
        if (const Value* t = v.find("transform")) o.transform = parseTransform(*t, member(place, "transform"));
        return o;
    }

    MeshSource parseMesh(const Value& v, const std::string& place) const {
        checkKeys(v, place, {"vertices", "triangles", "quad", "file"});
        const bool isInline = v.find("vertices") || v.find("triangles");
        const int kinds = int(isInline) + int(v.find("quad") != nullptr) + int(v.find("file") != nullptr);
        if (kinds != 1)
            fail(place, std::string(kinds == 0 ? "a mesh needs" : "a mesh has exactly one of") +
                            " \"vertices\" with \"triangles\", \"quad\" or \"file\"");
        MeshSource mesh;
        if (const Value* file = v.find("file")) {
            mesh.kind = MeshSource::Kind::File;
            mesh.file = text(*file, member(place, "file"));
            if (mesh.file.empty()) fail(member(place, "file"), "mesh file path is empty");
            if (mesh.file.find('\0') != std::string::npos) fail(member(place, "file"), "mesh file path contains a NUL character");
        } else if (const Value* quad = v.find("quad")) {
            mesh.kind = MeshSource::Kind::Quad;
            const std::string here = member(place, "quad");
            array(*quad, here, 4, "vertices");
            for (size_t i = 0; i < 4; ++i) mesh.quad[i] = vec3(quad->array[i], item(here, i));
        } else {
            mesh.kind = MeshSource::Kind::Inline;
            const std::string vPlace = member(place, "vertices"), tPlace = member(place, "triangles");
            const Value& vertices = required(v, place, "vertices");
            const Value& triangles = required(v, place, "triangles");
            expectType(vertices, Type::Array, vPlace);
            expectType(triangles, Type::Array, tPlace);
            TriangleMesh& m = mesh.inlineMesh;
            m.vertices.reserve(vertices.array.size());
            for (size_t i = 0; i < vertices.array.size(); ++i) m.vertices.push_back(vec3(vertices.array[i], item(vPlace, i)));
            m.triangles.reserve(triangles.array.size());
            for (size_t i = 0; i < triangles.array.size(); ++i) {
                const std::string here = item(tPlace, i);
                const Value& t = array(triangles.array[i], here, 3, "vertex indices");
                int idx[3];
                for (size_t k = 0; k < 3; ++k) {
                    const double n = integer(t.array[k], item(here, k));
                    if (n < 0 || n >= double(m.vertices.size()))
                        fail(item(here, k), "index " + shortestNumber(n) + " is out of range (the mesh has " +
                                                std::to_string(m.vertices.size()) + " vertices)");
                    idx[k] = int(n);
                }
                m.triangles.emplace_back(idx[0], idx[1], idx[2]);
            }
        }
        return mesh;
    }

    Transform parseTransform(const Value& v, const std::string& place) const {
        checkKeys(v, place, {"scale", "rotate", "translate", "matrix"});
        Transform t;
        if (const Value* m = v.find("matrix")) {
            const std::string here = member(place, "matrix");
            if (v.object.size() > 1) fail(here, "a matrix cannot be combined with scale, rotate or translate");
            array(*m, here, 16, "numbers (row-major 4x4)");
            t.isMatrix = true;
            for (size_t i = 0; i < 16; ++i) t.matrix[i / 4][i % 4] = number(m->array[i], item(here, i));
            for (int j = 0; j < 4; ++j)
                if (t.matrix[3][j] != (j == 3 ? 1.0 : 0.0))
                    fail(item(here, size_t(12 + j)), "the last row of the matrix must be 0 0 0 1");
            // Invertible: the 3x3 part's determinant against the product of its row lengths
            // (Hadamard's bound), so that scale does not decide.
            const M44d& a = t.matrix;
            const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                               a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
            double bound = 1;
            for (int i = 0; i < 3; ++i) bound *= std::sqrt(a[i][0] * a[i][0] + a[i][1] * a[i][1] + a[i][2] * a[i][2]);
            if (!std::isfinite(det) || !(std::abs(det) > 1e-12 * bound)) fail(here, "the matrix is not invertible");
            return t;
        }
        if (const Value* s = v.find("scale")) {
            const std::string here = member(place, "scale");
            if (s->type == Type::Number) {
                t.scale = V3d(s->number, s->number, s->number);
            } else if (s->type == Type::Array) {
                t.scale = vec3(*s, here);
                t.uniformScale = false;
            } else {
                fail(here, std::string("expected a number or an array of 3 numbers, got ") + json::describe(s->type));
            }
            // A zero scale would flatten the object: the transform would not be invertible,
            // which the matrix form rejects too.
            if (t.scale.x == 0 || t.scale.y == 0 || t.scale.z == 0) fail(here, "scale must be non-zero");
        }
        if (const Value* r = v.find("rotate")) {
            const std::string here = member(place, "rotate");
            array(*r, here, 4, "numbers (axis x, y, z, degrees)");
            t.hasRotate = true;
            t.rotateAxis = V3d(number(r->array[0], item(here, 0)), number(r->array[1], item(here, 1)),
                               number(r->array[2], item(here, 2)));
            t.rotateDeg = number(r->array[3], item(here, 3));
            if (t.rotateAxis == V3d(0, 0, 0)) fail(here, "the rotation axis must be non-zero");
        }
        if (const Value* tr = v.find("translate")) t.translate = vec3(*tr, member(place, "translate"));
        return t;
    }

    Light parseLight(const Value& v, const std::string& place) {
        expectType(v, Type::Object, place);
        Light l;
        const std::string type = text(required(v, place, "type"), member(place, "type"));
        const std::string what = "a " + type + " light";
        if (type == "point") {
            l.type = LightType::Point;
            checkKeys(v, place, {"name", "type", "position", "intensity", "lumens", "candela", "color", "temperature", "group", "on",
                                 "maintenance_factor"}, what);
        } else if (type == "spot") {
            l.type = LightType::Spot;
            checkKeys(v, place, {"name", "type", "position", "direction", "intensity", "cone_angle", "falloff_start",
                                 "lumens", "candela", "color", "temperature", "group", "on", "maintenance_factor"}, what);
        } else if (type == "directional") {
            l.type = LightType::Directional;
            checkKeys(v, place, {"name", "type", "direction", "irradiance", "group", "on"}, what);
        } else if (type == "luminaire") {
            l.type = LightType::Luminaire;
            checkKeys(v, place, {"name", "type", "file", "position", "direction", "rotation", "lumens", "color",
                                 "temperature", "group", "on", "maintenance_factor", "luminous_area"}, what);
            l.name = parseName(v, place);
            l.position = vec3(required(v, place, "position"), member(place, "position"));
            l.direction = direction(required(v, place, "direction"), member(place, "direction"));
            l.luminaire = parseLuminaire(v, place);
            parseGroupAndSwitch(v, place, l);
            if (const Value* mf = v.find("maintenance_factor"))
                l.maintenance = parseMaintenance(*mf, member(place, "maintenance_factor"));
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
        if (l.photometric)
            l.intensity = photometricIntensity(*l.photometric, l.type == LightType::Spot
                                                                   ? spotSolidAngle(l.coneAngleDeg, l.falloffStartDeg)
                                                                   : pointSolidAngle());
        return l;
    }

    // The additions every light type takes (README, "Light groups"): "group", a non-empty name
    // (groups are their own namespace: a group may share a light's name), and "on", a boolean.
    void parseGroupAndSwitch(const Value& v, const std::string& place, Light& l) const {
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

    // A luminaire's keys (README): its file, rotation about the nadir, and optional lumens and
    // colour (color or temperature, not both). The file itself is read by resolve().
    LuminaireSpec parseLuminaire(const Value& v, const std::string& place) const {
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
        const Value* colourValue = v.find("color");
        const Value* temperature = v.find("temperature");
        if (colourValue && temperature) fail(place, "give color or temperature, not both");
        if (colourValue) {
            s.colour = colour(*colourValue, member(place, "color"), false);
            if (!(luminance(*s.colour) > 0)) fail(member(place, "color"), "must have a positive luminance");
        }
        if (temperature)
            s.temperatureK = numberIn(*temperature, member(place, "temperature"), 1000, false, 40000, false, " kelvin");
        if (const Value* area = v.find("luminous_area")) {
            const std::string here = member(place, "luminous_area");
            const Value& a = array(*area, here, 2, "numbers (width, length in metres)");
            s.luminousAreaM = V2d(numberIn(a.array[0], item(here, 0), 0, true, 1000, false, " m"),
                                  numberIn(a.array[1], item(here, 1), 0, true, 1000, false, " m"));
        }
        return s;
    }

    // The photometric keys of a point or spot light (README): exactly one of intensity, lumens
    // and candela; with lumens or candela, at most one of color and temperature.
    std::optional<PhotometricSpec> parsePhotometric(const Value& v, const std::string& place) const {
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
        if (colourValue && temperature) fail(place, "give color or temperature, not both");
        if (colourValue) {
            p.colour = colour(*colourValue, member(place, "color"), false);
            if (!(luminance(*p.colour) > 0)) fail(member(place, "color"), "must have a positive luminance");
        }
        if (temperature)
            p.temperatureK = numberIn(*temperature, member(place, "temperature"), 1000, false, 40000, false, " kelvin");
        return p;
    }

    // SPEC.md section 5: the illuminance, the disc's size, and its place: a direction or a local time.
    SunSpec parseSun(const Value& v, const std::string& place, Light& l) const {
        SunSpec s;
        const std::string lux = member(place, "illuminance");
        s.illuminanceLux = number(required(v, place, "illuminance"), lux);
        if (!(s.illuminanceLux >= 0)) fail(lux, "must be at least 0, got " + shortestNumber(s.illuminanceLux));
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

    // A maintenance factor (README, "Maintained values"): a number, or CIE 97's factors, each in
    // (0, 1], at least one of them.
    MaintenanceFactor parseMaintenance(const Value& v, const std::string& place) const {
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

    // A task area (README, "Task areas"): a named rectangle as a calculation grid's, its activity
    // and its glare observers.
    TaskArea parseTaskArea(const Value& v, const std::string& place, const std::vector<TaskArea>& earlier) const {
        checkKeys(v, place, {"name", "corner", "u", "v", "spacing", "activity", "observers"});
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
            if (!findActivity(a.activity))
                fail(member(place, "activity"), "unknown activity " + quote(a.activity) +
                                                    " (expected a reference number of EN 12464-1's table: `lucerna standards` lists them)");
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

    ProjectInfo parseProject(const Value& v, const std::string& place) const {
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

    Site parseSite(const Value& v, const std::string& place) const {
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

    Sky parseSky(const Value& v, const std::string& place) const {
        checkKeys(v, place, {"model", "cie_type", "zenith_luminance", "horizontal_illuminance", "ground_reflectance"});
        Sky s;
        const std::string modelPlace = member(place, "model");
        const std::string model = text(required(v, place, "model"), modelPlace);
        if (model == "uniform") s.model = SkyModelType::Uniform;
        else if (model == "cie_overcast") s.model = SkyModelType::CieOvercast;
        else if (model == "cie_general") s.model = SkyModelType::CieGeneral;
        else fail(modelPlace, "unknown sky model " + quote(model) + " (expected uniform, cie_overcast or cie_general)");
        const Value* type = v.find("cie_type");
        if (s.model == SkyModelType::CieGeneral) {
            const std::string here = member(place, "cie_type");
            const double t = integer(required(v, place, "cie_type"), here);
            if (t < 1 || t > 15) fail(here, "must be from 1 to 15, got " + shortestNumber(t));
            s.cieType = int(t);
        } else if (type) {
            fail(member(place, "cie_type"), "only for the cie_general model");
        }
        const Value* lz = v.find("zenith_luminance");
        const Value* eh = v.find("horizontal_illuminance");
        if ((lz != nullptr) == (eh != nullptr))
            fail(place, "give exactly one of zenith_luminance and horizontal_illuminance");
        const std::string quantityPlace = member(place, lz ? "zenith_luminance" : "horizontal_illuminance");
        const double quantity = number(lz ? *lz : *eh, quantityPlace);
        if (!(quantity >= 0) || !std::isfinite(quantity))
            fail(quantityPlace, "must be a finite number at least 0, got " + shortestNumber(quantity));
        (lz ? s.zenithLuminance : s.horizontalIlluminance) = quantity;
        if (const Value* g = v.find("ground_reflectance")) {
            s.groundReflectance = numberIn(*g, member(place, "ground_reflectance"), 0, false, 1, false);
            s.groundReflectanceGiven = true;
        }
        return s;
    }

    // The rules that span keys: one sun at most, a local time needs a site, a CIE general sky a sun.
    void checkDaylight(const Scene& scene) const {
        int suns = 0;
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            const Light& l = scene.lights[i];
            if (l.type != LightType::Sun) continue;
            if (++suns > 1) fail(item("lights", i), "a scene has at most one sun");
            if (l.sun && l.sun->time && !scene.site)
                fail(member(item("lights", i), "time"), "a sun placed by time needs the scene's \"site\"");
        }
        if (scene.sky && scene.sky->model == SkyModelType::CieGeneral && suns == 0)
            fail("sky.model", "a cie_general sky needs a light of type \"sun\"");
    }

    std::string file_;
    std::unordered_map<std::string, std::string> names_;  // name -> where it was first used
};

}  // namespace

Scene parseScene(const std::string& bytes, const std::string& path, LoadReport* report) {
    json::Value root;
    try {
        root = json::parse(bytes);
    } catch (const json::ParseError& e) {
        throw SceneError(path + ": line " + std::to_string(e.line()) + ": " + e.what());
    }
    Scene scene = SceneParser(path).parse(root);
    scene.baseDir = QFileInfo(QString::fromStdString(path)).absolutePath().toStdString();
    resolveScene(scene, report, path);
    return scene;
}

Scene loadScene(const std::string& path, LoadReport* report) {
    if (const std::string kind = nonRegularFileKind(path); !kind.empty())
        throw SceneError(path + ": cannot read the file: not a regular file (" + kind + ")");
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly)) throw SceneError(path + ": cannot read the file: " + file.errorString().toStdString());
    const QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError)
        throw SceneError(path + ": cannot read the file: " + file.errorString().toStdString());
    return parseScene(bytes.toStdString(), path, report);
}

}  // namespace lucerna
