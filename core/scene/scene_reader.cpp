// Reading SPEC.md section 1: JSON text -> validated Scene (SceneParser, scene_parser.h) ->
// world-space meshes (scene_resolve.h). Here: the top level, the camera, materials and objects.

#include "core/scene/scene_parser.h"

#include "core/number_format.h"
#include "core/regular_file.h"
#include "core/scene/scene_io.h"
#include "core/scene/scene_resolve.h"

#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {

inline constexpr int kMaxResolution = 16384;

}  // namespace

Scene SceneParser::parse(const Value& root) {
    Scene scene;
    const std::string top = kTopLevel;
    expectType(root, Type::Object, top);
    // The version first: a newer file may well have keys this reader does not know.
    const Value& version = required(root, top, "lucerna");
    const double v = integer(version, "lucerna");
    if (v != 1) fail("lucerna", "unsupported format version " + shortestNumber(v) + " (this reader reads version 1)");
    checkKeys(root, top, {"lucerna", "meters_per_unit", "camera", "materials", "objects", "lights", "site", "sky",
                         "maintenance_factor", "lighting_standard", "task_areas", "project", "energy", "rooms"});
    scene.version = 1;
    if (const Value* mpu = root.find("meters_per_unit")) {
        scene.metersPerUnit = number(*mpu, "meters_per_unit");
        if (!(scene.metersPerUnit > 0))
            fail("meters_per_unit", "must be positive, got " + shortestNumber(scene.metersPerUnit));
        scene.metersPerUnitGiven = true;
    }
    scene.camera = parseCamera(required(root, top, "camera"), "camera");
    parseMaterials(required(root, top, "materials"), "materials", scene);
    // Before the objects, which name their room.
    if (const Value* rooms = root.find("rooms")) {
        expectType(*rooms, Type::Array, "rooms");
        for (size_t i = 0; i < rooms->array.size(); ++i) scene.rooms.push_back(parseRoom(rooms->array[i], item("rooms", i), scene));
    }
    const Value& objects = required(root, top, "objects");
    expectType(objects, Type::Array, "objects");
    for (size_t i = 0; i < objects.array.size(); ++i)
        scene.objects.push_back(parseObject(objects.array[i], item("objects", i), scene));
    checkRooms(scene);
    if (const Value* lights = root.find("lights")) {
        expectType(*lights, Type::Array, "lights");
        for (size_t i = 0; i < lights->array.size(); ++i)
            scene.lights.push_back(parseLight(lights->array[i], item("lights", i)));
    }
    if (const Value* site = root.find("site")) scene.site = parseSite(*site, "site");
    if (const Value* sky = root.find("sky")) scene.sky = parseSky(*sky, "sky");
    checkDaylight(scene);
    if (const Value* mf = root.find("maintenance_factor")) scene.maintenance = parseMaintenance(*mf, "maintenance_factor");
    if (const Value* standard = root.find("lighting_standard"))
        scene.lightingStandard = parseLightingStandard(*standard, "lighting_standard");
    if (const Value* areas = root.find("task_areas")) {
        expectType(*areas, Type::Array, "task_areas");
        for (size_t i = 0; i < areas->array.size(); ++i)
            scene.taskAreas.push_back(parseTaskArea(areas->array[i], item("task_areas", i), scene.taskAreas));
    }
    if (const Value* project = root.find("project")) scene.project = parseProject(*project, "project");
    if (const Value* energy = root.find("energy")) scene.energy = parseEnergy(*energy, "energy");
    return scene;
}

Camera SceneParser::parseCamera(const Value& v, const std::string& place) const {
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

void SceneParser::parseMaterials(const Value& v, const std::string& place, Scene& scene) const {
    expectType(v, Type::Object, place);
    for (const json::Member& m : v.object) {
        const std::string here = member(place, m.key);
        expectType(m.value, Type::Object, here);
        Material mat;
        mat.name = m.key;
        const std::string type = text(required(m.value, here, "type"), member(here, "type"));
        const std::string what = "a " + type + " material";
        const auto colourKey = [&](const char* key, bool fraction) {
            return colour(required(m.value, here, key), member(here, key), fraction);
        };
        // The materials of one colour: "type" and that colour's key.
        const auto onlyColour = [&](const char* key, bool fraction) {
            checkKeys(m.value, here, {"type", key}, what);
            return colourKey(key, fraction);
        };
        if (type == "diffuse") {
            mat.type = MaterialType::Diffuse;
            mat.albedo = onlyColour("albedo", true);
        } else if (type == "glossy") {
            mat.type = MaterialType::Glossy;
            checkKeys(m.value, here, {"type", "albedo", "specular", "roughness"}, what);
            mat.albedo = colourKey("albedo", true);
            mat.specular = colourKey("specular", true);
            mat.roughness = numberIn(required(m.value, here, "roughness"), member(here, "roughness"), 0, true, 1, false);
        } else if (type == "mirror") {
            mat.type = MaterialType::Mirror;
            mat.reflectance = onlyColour("reflectance", true);
        } else if (type == "dielectric") {
            mat.type = MaterialType::Dielectric;
            checkKeys(m.value, here, {"type", "ior"}, what);
            mat.ior = number(required(m.value, here, "ior"), member(here, "ior"));
            if (!(mat.ior > 0)) fail(member(here, "ior"), "must be positive, got " + shortestNumber(mat.ior));
        } else if (type == "glazing") {
            mat.type = MaterialType::Glazing;
            mat.transmittance = onlyColour("transmittance", true);
        } else if (type == "emitter") {
            mat.type = MaterialType::Emitter;
            mat.radiance = onlyColour("radiance", false);
        } else {
            fail(member(here, "type"), "unknown material type " + quote(type) +
                                           " (expected diffuse, glossy, mirror, dielectric, emitter or glazing)");
        }
        scene.materials.push_back(std::move(mat));
    }
}

Object SceneParser::parseObject(const Value& v, const std::string& place, const Scene& scene) {
    checkKeys(v, place, {"name", "material", "mesh", "transform", "room", "portal"});
    Object o;
    o.name = parseName(v, place);
    o.material = text(required(v, place, "material"), member(place, "material"));
    if (scene.materialIndex(o.material) < 0)
        fail(member(place, "material"), "unknown material " + quote(o.material));
    o.mesh = parseMesh(required(v, place, "mesh"), member(place, "mesh"));
    if (const Value* t = v.find("transform")) o.transform = parseTransform(*t, member(place, "transform"));
    if (const Value* room = v.find("room")) {
        o.room = text(*room, member(place, "room"));
        if (std::none_of(scene.rooms.begin(), scene.rooms.end(), [&](const Room& r) { return r.name == o.room; }))
            fail(member(place, "room"), "unknown room " + quote(o.room) + " (rooms are listed under \"rooms\")");
    }
    if (const Value* portal = v.find("portal")) {
        expectType(*portal, Type::Boolean, member(place, "portal"));
        o.portal = portal->boolean;
    }
    return o;
}

MeshSource SceneParser::parseMesh(const Value& v, const std::string& place) const {
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

Transform SceneParser::parseTransform(const Value& v, const std::string& place) const {
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
