// The scene file of SPEC.md section 1: every rejection with its one-line message, exact round
// trips, atomic saves, transforms, the bundled scenes, the features a scene uses. Mesh files:
// test_mesh_files.

#include "core/mesh/mesh_file.h"
#include "core/scene/scene_io.h"
#include "scene_text.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cfloat>
#include <cstdio>
#include <unistd.h>

using namespace lucerna;
using namespace lucerna::test;

namespace {

bool near(const V3d& a, const V3d& b, double eps = 1e-12) { return (a - b).length() <= eps; }

}  // namespace

class TestSceneIo : public QObject {
    Q_OBJECT

private slots:
    void rejects_data();
    void rejects();
    void rejectsUnreadableSceneFile();
    void acceptsOptionalAndBoundaryValues();
    void loadsCornellBox();
    void loadsInterior();
    void roundTrips_data();
    void roundTrips();
    void roundTripsAwkwardNumbers();
    void roundTripsGroupsAndSwitches();
    void savesAtomically();
    void appliesTransforms();
    void analysesFeatures();
};

void TestSceneIo::rejects_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("place");
    QTest::addColumn<QString>("problem");
    const auto row = [](const char* tag, const std::string& json, const char* place, const char* problem) {
        QTest::newRow(tag) << QByteArray::fromStdString(json) << QString(place) << QString(problem);
    };
    const auto with = [](auto change) { Parts p; change(p); return p.text(); };

    // Bad JSON: the place is the line.
    row("syntax: trailing comma", with([](Parts& p) { p.camera = cameraWith(","); }), "line 3", "expected a key string");
    row("syntax: unterminated", Parts().text().substr(0, 40), "line 3", "end of input");
    row("syntax: duplicate key", with([](Parts& p) { p.camera = cameraWith(R"(, "fov_y": 50)"); }), "line 3", "given twice");
    row("syntax: NaN", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "fov_y": NaN, "resolution": [64, 48])"); }), "line 3", "unexpected character 'N'");
    row("syntax: infinite number", with([](Parts& p) { p.camera = camera(R"("position": [0, 1e999, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [64, 48])"); }), "line 3", "too large (not finite)");
    row("syntax: trailing garbage", Parts().text() + "}", "line 8", "after the end of the JSON value");
    row("syntax: deep nesting", with([](Parts& p) { p.lights = R"("lights": )" + std::string(300, '[') + std::string(300, ']'); }), "line 6", "nested deeper than 256");
    row("syntax: invalid UTF-8", with([](Parts& p) { p.objects = object("{\"name\": \"fl\xC3\x28r\"}"); }), "line 5", "invalid UTF-8");
    row("syntax: lone surrogate", with([](Parts& p) { p.objects = object(R"({"name": "\ud800"})"); }), "line 5", "surrogate");
    row("syntax: raw control character", with([](Parts& p) { p.objects = object("{\"name\": \"a\tb\"}"); }), "line 5", "control character");

    // The document.
    row("top level not an object", "[1, 2]", "top level", "expected an object, got an array");
    row("missing version", with([](Parts& p) { p.lucerna = R"("lucerna_": 1)"; }), "lucerna", "required key is missing");
    row("version 2", with([](Parts& p) { p.lucerna = R"("lucerna": 2)"; }), "lucerna", "unsupported format version 2");
    row("version not an integer", with([](Parts& p) { p.lucerna = R"("lucerna": 1.5)"; }), "lucerna", "expected an integer, got 1.5");
    row("version a string", with([](Parts& p) { p.lucerna = R"("lucerna": "1")"; }), "lucerna", "expected a number, got a string");
    row("unknown top-level key", with([](Parts& p) { p.lucerna += R"(, "colour": 1)"; }), "colour", "unknown key");
    row("missing camera", with([](Parts& p) { p.camera.clear(); }), "camera", "required key is missing");
    row("missing materials", with([](Parts& p) { p.materials.clear(); }), "materials", "required key is missing");
    row("missing objects", with([](Parts& p) { p.objects.clear(); }), "objects", "required key is missing");
    row("meters_per_unit zero", with([](Parts& p) { p.lucerna += R"(, "meters_per_unit": 0)"; }), "meters_per_unit", "must be positive, got 0");
    row("meters_per_unit negative", with([](Parts& p) { p.lucerna += R"(, "meters_per_unit": -0.001)"; }), "meters_per_unit", "must be positive");

    // Camera.
    row("camera unknown key", with([](Parts& p) { p.camera = cameraWith(R"(, "fov_x": 3)"); }), "camera.fov_x", "unknown key");
    row("camera missing fov_y", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "resolution": [64, 48])"); }), "camera.fov_y", "required key is missing");
    row("fov_y zero", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 0, "resolution": [64, 48])"); }), "camera.fov_y", "must be in (0, 180) degrees, got 0");
    row("fov_y 180", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 180, "resolution": [64, 48])"); }), "camera.fov_y", "must be in (0, 180)");
    row("resolution zero", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [0, 48])"); }), "camera.resolution[0]", "must be from 1 to 16384, got 0");
    row("resolution too large", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [64, 16385])"); }), "camera.resolution[1]", "must be from 1 to 16384, got 16385");
    row("resolution negative", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [-64, 48])"); }), "camera.resolution[0]", "must be from 1 to 16384");
    row("resolution not an integer", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [64.5, 48])"); }), "camera.resolution[0]", "expected an integer, got 64.5");
    row("resolution one number", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [64])"); }), "camera.resolution", "expected an array of 2 integers (width, height), got 1 element");
    row("target equals position", with([](Parts& p) { p.camera = camera(R"("position": [0, 1, 5], "target": [0, 1, 5], "fov_y": 40, "resolution": [64, 48])"); }), "camera.target", "target equals position");
    row("up parallel to view", with([](Parts& p) { p.camera = camera(R"("position": [0, 5, 0], "target": [0, 0, 0], "up": [0, 2, 0], "fov_y": 40, "resolution": [64, 48])"); }), "camera.up", "parallel to the view direction");
    row("up zero", with([](Parts& p) { p.camera = cameraWith(R"(, "up": [0, 0, 0])"); }), "camera.up", "must be non-zero");
    row("position too short", with([](Parts& p) { p.camera = camera(R"("position": [0, 1], "target": [0, 1, 0], "fov_y": 40, "resolution": [64, 48])"); }), "camera.position", "expected an array of 3 numbers, got 2 elements");
    row("position element a string", with([](Parts& p) { p.camera = camera(R"("position": [0, "1", 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [64, 48])"); }), "camera.position[1]", "expected a number, got a string");

    // Materials.
    row("materials an array", with([](Parts& p) { p.materials = R"("materials": [])"; }), "materials", "expected an object, got an array");
    row("material unknown type", with([](Parts& p) { p.materials = material(R"({"type": "plastic"})"); }), "materials.white.type", "unknown material type \"plastic\"");
    row("material missing type", with([](Parts& p) { p.materials = material(R"({"albedo": [0.5, 0.5, 0.5]})"); }), "materials.white.type", "required key is missing");
    row("material key of another type", with([](Parts& p) { p.materials = material(R"({"type": "diffuse", "albedo": [0.5, 0.5, 0.5], "roughness": 0.5})"); }), "materials.white.roughness", "unknown key for a diffuse material");
    row("albedo above 1", with([](Parts& p) { p.materials = material(R"({"type": "diffuse", "albedo": [0.5, 1.01, 0.5]})"); }), "materials.white.albedo[1]", "must be in [0, 1], got 1.01");
    row("albedo below 0", with([](Parts& p) { p.materials = material(R"({"type": "diffuse", "albedo": [-0.1, 0.5, 0.5]})"); }), "materials.white.albedo[0]", "must be in [0, 1], got -0.1");
    row("diffuse missing albedo", with([](Parts& p) { p.materials = material(R"({"type": "diffuse"})"); }), "materials.white.albedo", "required key is missing");
    row("glossy roughness zero", with([](Parts& p) { p.materials = material(R"({"type": "glossy", "albedo": [0, 0, 0], "specular": [1, 1, 1], "roughness": 0})"); }), "materials.white.roughness", "must be in (0, 1], got 0");
    row("glossy roughness above 1", with([](Parts& p) { p.materials = material(R"({"type": "glossy", "albedo": [0, 0, 0], "specular": [1, 1, 1], "roughness": 1.5})"); }), "materials.white.roughness", "must be in (0, 1]");
    row("glossy specular above 1", with([](Parts& p) { p.materials = material(R"({"type": "glossy", "albedo": [0, 0, 0], "specular": [1, 2, 1], "roughness": 0.5})"); }), "materials.white.specular[1]", "must be in [0, 1], got 2");
    row("glossy missing specular", with([](Parts& p) { p.materials = material(R"({"type": "glossy", "albedo": [0, 0, 0], "roughness": 0.5})"); }), "materials.white.specular", "required key is missing");
    row("mirror reflectance above 1", with([](Parts& p) { p.materials = material(R"({"type": "mirror", "reflectance": [1, 1, 1.5]})"); }), "materials.white.reflectance[2]", "must be in [0, 1]");
    row("dielectric ior zero", with([](Parts& p) { p.materials = material(R"({"type": "dielectric", "ior": 0})"); }), "materials.white.ior", "must be positive, got 0");
    row("dielectric ior negative", with([](Parts& p) { p.materials = material(R"({"type": "dielectric", "ior": -1.5})"); }), "materials.white.ior", "must be positive");
    row("emitter radiance negative", with([](Parts& p) { p.materials = material(R"({"type": "emitter", "radiance": [1, -2, 1]})"); }), "materials.white.radiance[1]", "must be at least 0, got -2");
    row("material name quoted in path", with([](Parts& p) { p.materials = R"("materials": {"white": {"type": "diffuse", "albedo": [1, 1, 1]}, "my glass": {"type": "dielectric", "ior": "1.5"}})"; }), "materials[\"my glass\"].ior", "expected a number, got a string");

    // Objects and meshes.
    row("objects an object", with([](Parts& p) { p.objects = R"("objects": {})"; }), "objects", "expected an array, got an object");
    row("object missing name", with([](Parts& p) { p.objects = object(R"({"material": "white", "mesh": {"file": "x.obj"}})"); }), "objects[0].name", "required key is missing");
    row("object name a number", with([](Parts& p) { p.objects = object(R"({"name": 7, "material": "white", "mesh": {"file": "x.obj"}})"); }), "objects[0].name", "expected a string, got a number");
    row("object unknown key", with([](Parts& p) { p.objects = meshObject(R"({"file": "x.obj"})", R"(, "visible": true)"); }), "objects[0].visible", "unknown key");
    row("duplicate object names", with([](Parts& p) { p.objects = object(R"({"name": "a", "material": "white", "mesh": {"quad": [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]}}, )"
                                                                          R"({"name": "a", "material": "white", "mesh": {"quad": [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]}})"); }),
        "objects[1].name", "name \"a\" is already used by objects[0].name");
    row("light named like an object", with([](Parts& p) { p.lights = light(R"({"name": "floor", "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1]})"); }), "lights[0].name", "name \"floor\" is already used by objects[0].name");
    row("duplicate light names", with([](Parts& p) { p.lights = light(R"({"name": "b", "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1]}, {"name": "b", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]})"); }), "lights[1].name", "already used by lights[0].name");
    row("unknown material", with([](Parts& p) { p.objects = object(R"({"name": "x", "material": "gold", "mesh": {"file": "x.obj"}})"); }), "objects[0].material", "unknown material \"gold\"");
    row("material reference with no materials", with([](Parts& p) { p.materials = R"("materials": {})"; }), "objects[0].material", "unknown material \"white\"");
    row("mesh missing", with([](Parts& p) { p.objects = object(R"({"name": "x", "material": "white"})"); }), "objects[0].mesh", "required key is missing");
    row("mesh empty", with([](Parts& p) { p.objects = meshObject("{}"); }), "objects[0].mesh", "a mesh needs");
    row("mesh two kinds", with([](Parts& p) { p.objects = meshObject(R"({"file": "a.obj", "quad": [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]})"); }), "objects[0].mesh", "exactly one of");
    row("mesh unknown key", with([](Parts& p) { p.objects = meshObject(R"({"file": "a.obj", "normals": []})"); }), "objects[0].mesh.normals", "unknown key");
    row("quad with three vertices", with([](Parts& p) { p.objects = meshObject(R"({"quad": [[0, 0, 0], [1, 0, 0], [1, 0, 1]]})"); }), "objects[0].mesh.quad", "expected an array of 4 vertices, got 3 elements");
    row("inline missing triangles", with([](Parts& p) { p.objects = meshObject(R"({"vertices": [[0, 0, 0]]})"); }), "objects[0].mesh.triangles", "required key is missing");
    row("inline vertex of two numbers", with([](Parts& p) { p.objects = meshObject(R"({"vertices": [[0, 0, 0], [1, 0]], "triangles": []})"); }), "objects[0].mesh.vertices[1]", "expected an array of 3 numbers");
    row("index out of range", with([](Parts& p) { p.objects = meshObject(R"({"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2], [0, 2, 3]]})"); }), "objects[0].mesh.triangles[1][2]", "index 3 is out of range (the mesh has 3 vertices)");
    row("index negative", with([](Parts& p) { p.objects = meshObject(R"({"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, -1, 2]]})"); }), "objects[0].mesh.triangles[0][1]", "index -1 is out of range");
    row("index not an integer", with([](Parts& p) { p.objects = meshObject(R"({"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1.5, 2]]})"); }), "objects[0].mesh.triangles[0][1]", "expected an integer, got 1.5");
    row("triangle of four indices", with([](Parts& p) { p.objects = meshObject(R"({"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2, 0]]})"); }), "objects[0].mesh.triangles[0]", "expected an array of 3 vertex indices, got 4 elements");
    row("file path not a string", with([](Parts& p) { p.objects = meshObject(R"({"file": ["a.obj"]})"); }), "objects[0].mesh.file", "expected a string, got an array");
    row("file path empty", with([](Parts& p) { p.objects = meshObject(R"({"file": ""})"); }), "objects[0].mesh.file", "mesh file path is empty");
    row("missing mesh file", with([](Parts& p) { p.objects = meshObject(R"({"file": "meshes/no-such-file.obj"})"); }), "objects[0].mesh.file", "no such file");
    row("mesh file of unknown format", with([](Parts& p) { p.objects = meshObject(R"({"file": "every-key.json"})"); }), "objects[0].mesh.file", "unsupported mesh format \"json\"");
    row("mesh file is a folder", with([](Parts& p) { p.objects = meshObject(R"({"file": "meshes"})"); }), "objects[0].mesh.file", "not a regular file");
    row("emitter of zero area", with([](Parts& p) { p.objects = object(R"({"name": "floor", "material": "white", "mesh": {"quad": [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]}}, )"
                                                                        R"({"name": "light", "material": "lamp", "mesh": {"quad": [[0, 1, 0], [1, 1, 0], [2, 1, 0], [3, 1, 0]]}})"); }),
        "objects[1].mesh", "the objects of emitter material \"lamp\" have zero total area");

    // Transforms.
    row("transform unknown key", with([](Parts& p) { p.objects = withTransform(R"({"rotation": [0, 1, 0, 30]})"); }), "objects[0].transform.rotation", "unknown key");
    row("scale zero", with([](Parts& p) { p.objects = withTransform(R"({"scale": [1, 0, 1]})"); }), "objects[0].transform.scale", "scale must be non-zero");
    row("scale a string", with([](Parts& p) { p.objects = withTransform(R"({"scale": "2"})"); }), "objects[0].transform.scale", "expected a number or an array of 3 numbers, got a string");
    row("rotate zero axis", with([](Parts& p) { p.objects = withTransform(R"({"rotate": [0, 0, 0, 30]})"); }), "objects[0].transform.rotate", "rotation axis must be non-zero");
    row("rotate without angle", with([](Parts& p) { p.objects = withTransform(R"({"rotate": [0, 1, 0]})"); }), "objects[0].transform.rotate", "expected an array of 4 numbers");
    row("matrix of 15 numbers", with([](Parts& p) { p.objects = withTransform(R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0]})"); }), "objects[0].transform.matrix", "expected an array of 16 numbers");
    row("matrix last row", with([](Parts& p) { p.objects = withTransform(R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, 0, 1]})"); }), "objects[0].transform.matrix[13]", "last row of the matrix must be 0 0 0 1");
    row("matrix last row scaled", with([](Parts& p) { p.objects = withTransform(R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2]})"); }), "objects[0].transform.matrix[15]", "last row of the matrix must be 0 0 0 1");
    row("matrix singular", with([](Parts& p) { p.objects = withTransform(R"({"matrix": [1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 1, 0, 0, 0, 0, 1]})"); }), "objects[0].transform.matrix", "not invertible");
    row("matrix with translate", with([](Parts& p) { p.objects = withTransform(R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], "translate": [1, 2, 3]})"); }), "objects[0].transform.matrix", "cannot be combined");
    row("matrix element a boolean", with([](Parts& p) { p.objects = withTransform(R"({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, true, 0, 0, 0, 0, 1]})"); }), "objects[0].transform.matrix[10]", "expected a number, got a boolean");

    // Lights.
    row("lights an object", with([](Parts& p) { p.lights = R"("lights": {})"; }), "lights", "expected an array, got an object");
    row("light unknown type", with([](Parts& p) { p.lights = light(R"({"name": "l", "type": "area"})"); }), "lights[0].type", "unknown light type \"area\"");
    row("light missing type", with([](Parts& p) { p.lights = light(R"({"name": "l", "position": [0, 0, 0]})"); }), "lights[0].type", "required key is missing");
    row("light missing name", with([](Parts& p) { p.lights = light(R"({"type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1]})"); }), "lights[0].name", "required key is missing");
    row("point light with direction", with([](Parts& p) { p.lights = light(R"({"name": "l", "type": "point", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1]})"); }), "lights[0].direction", "unknown key for a point light");
    row("point intensity negative", with([](Parts& p) { p.lights = light(R"({"name": "l", "type": "point", "position": [0, 2, 0], "intensity": [-1, 1, 1]})"); }), "lights[0].intensity[0]", "must be at least 0, got -1");
    row("spot intensity negative", with([](Parts& p) { p.lights = light(R"({"name": "s", "type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": [1, 1, -0.5], "cone_angle": 30})"); }), "lights[0].intensity[2]", "must be at least 0");
    row("spot zero direction", with([](Parts& p) { p.lights = light(R"({"name": "s", "type": "spot", "position": [0, 2, 0], "direction": [0, 0, 0], "intensity": [1, 1, 1], "cone_angle": 30})"); }), "lights[0].direction", "direction must be non-zero");
    row("spot missing cone", with([](Parts& p) { p.lights = light(R"({"name": "s", "type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1]})"); }), "lights[0].cone_angle", "required key is missing");
    row("cone_angle zero", with([](Parts& p) { p.lights = spot(R"("cone_angle": 0)"); }), "lights[0].cone_angle", "must be in (0, 180) degrees, got 0");
    row("cone_angle 180", with([](Parts& p) { p.lights = spot(R"("cone_angle": 180)"); }), "lights[0].cone_angle", "must be in (0, 180) degrees, got 180");
    row("falloff_start beyond cone", with([](Parts& p) { p.lights = spot(R"("cone_angle": 30, "falloff_start": 31)"); }), "lights[0].falloff_start", "must be in (0, 30] degrees (at most cone_angle), got 31");
    row("falloff_start zero", with([](Parts& p) { p.lights = spot(R"("cone_angle": 30, "falloff_start": 0)"); }), "lights[0].falloff_start", "must be in (0, 30]");
    row("directional zero direction", with([](Parts& p) { p.lights = light(R"({"name": "d", "type": "directional", "direction": [0, 0, 0], "irradiance": [1, 1, 1]})"); }), "lights[0].direction", "direction must be non-zero");
    row("directional irradiance negative", with([](Parts& p) { p.lights = light(R"({"name": "d", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, -3, 1]})"); }), "lights[0].irradiance[1]", "must be at least 0, got -3");
    row("directional with intensity", with([](Parts& p) { p.lights = light(R"({"name": "d", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1], "intensity": [1, 1, 1]})"); }), "lights[0].intensity", "unknown key for a directional light");
    // Groups and switches (README, "Light groups").
    row("group a number", with([](Parts& p) { p.lights = light(R"({"name": "l", "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1], "group": 3})"); }), "lights[0].group", "expected a string, got a number");
    row("group empty", with([](Parts& p) { p.lights = light(R"({"name": "l", "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1], "group": ""})"); }), "lights[0].group", "group name is empty");
    row("group with NUL", with([](Parts& p) { p.lights = light(R"({"name": "d", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1], "group": "a\u0000b"})"); }), "lights[0].group", "contains a NUL character");
    row("on a string", with([](Parts& p) { p.lights = light(R"({"name": "s", "type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1], "cone_angle": 30, "on": "no"})"); }), "lights[0].on", "expected a boolean, got a string");
    row("on a number", with([](Parts& p) { p.lights = light(R"({"name": "l", "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1], "on": 0})"); }), "lights[0].on", "expected a boolean, got a number");
}

void TestSceneIo::rejects() {
    QFETCH(QByteArray, json);
    QFETCH(QString, place);
    QFETCH(QString, problem);
    const QString message = QString::fromStdString(rejection(json.toStdString()));
    const QString head = QString::fromStdString(kCase) + ": " + place + ": ";
    QVERIFY2(message.startsWith(head), qPrintable("message: " + message + "\nexpected start: " + head));
    QVERIFY2(message.mid(head.size()).contains(problem), qPrintable("message: " + message + "\nexpected problem: " + problem));
    QVERIFY2(!message.contains('\n'), qPrintable(message));
}

void TestSceneIo::rejectsUnreadableSceneFile() {
    const std::string path = kData + "/no-such-scene.json";
    try {
        loadScene(path);
        QFAIL("a missing scene file was accepted");
    } catch (const SceneError& e) {
        QVERIFY2(std::string(e.what()).starts_with(path + ": cannot read the file"), e.what());
    }
}

void TestSceneIo::acceptsOptionalAndBoundaryValues() {
    Parts p;
    // No lights, no up, a hard-edged spot, integers written as 64.0, a BOM, a tiny number that
    // underflows to zero, escaped names.
    p.lights = spot(R"("cone_angle": 179.999, "falloff_start": 179.999)");
    p.camera = camera(R"("position": [0, 1, 5], "target": [1e-400, 1, 0], "fov_y": 179.9, "resolution": [64.0, 16384])");
    p.objects = object(R"({"name": "caf\u00e9 \ud83d\ude00", "material": "white", "mesh": {"quad": [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]}})");
    const Scene s = parseScene("\xEF\xBB\xBF" + p.text(), kCase);
    QCOMPARE(s.camera.up, V3d(0, 1, 0));
    QCOMPARE(s.camera.target, V3d(0, 1, 0));
    QCOMPARE(s.camera.width, 64);
    QCOMPARE(s.camera.height, 16384);
    QCOMPARE(s.objects[0].name, std::string("caf\xC3\xA9 \xF0\x9F\x98\x80"));
    QCOMPARE(*s.lights[0].falloffStartDeg, 179.999);
    QVERIFY(!s.metersPerUnitGiven);
    QCOMPARE(s.metersPerUnit, 1.0);

    // Lights may be left out; materials may be empty when nothing refers to one.
    const std::string bare = "{\"lucerna\": 1, " + p.camera + R"(, "materials": {}, "objects": []})";
    const Scene empty = parseScene(bare, kCase);
    QVERIFY(empty.lights.empty() && empty.materials.empty() && empty.objects.empty());

    // An unused emitter of zero area is no error, nor is a zero radiance.
    p.materials = R"("materials": {"white": {"type": "diffuse", "albedo": [0, 1, 0.5]}, "lamp": {"type": "emitter", "radiance": [0, 0, 0]}})";
    QCOMPARE(parseScene(p.text(), kCase).materials[1].radiance, Rgbd(0, 0, 0));
}

void TestSceneIo::loadsCornellBox() {
    for (const std::string& path : {kShared + "/scenes/cornell-box.json", kResources + "/scenes/cornell-box.json"}) {
        LoadReport report;
        const Scene s = loadScene(path, &report);
        QCOMPARE(s.metersPerUnit, 0.001);
        QCOMPARE(s.camera.position, V3d(278, 273, -800));
        QCOMPARE(s.camera.fovYDeg, 39.3077);
        QCOMPARE(s.camera.width, 256);
        QCOMPARE(int(s.materials.size()), 4);
        QCOMPARE(s.materials[0].name, std::string("white"));  // file order, not sorted
        QCOMPARE(s.materials[3].type, MaterialType::Emitter);
        QCOMPARE(s.materials[3].radiance, Rgbd(17, 12, 4));
        QCOMPARE(int(s.objects.size()), 8);
        QCOMPARE(s.objects[0].mesh.kind, MeshSource::Kind::Quad);
        QCOMPARE(s.objects[7].mesh.kind, MeshSource::Kind::Inline);
        QCOMPARE(s.objects[0].worldMesh->vertices[1], V3d(343, 548.7, 332));
        QCOMPARE(report.degenerateTrianglesDropped, 0);
        QVERIFY(report.warnings.empty());
        const SceneFeatures f = analyseFeatures(s);
        QCOMPARE(f.triangles, size_t(6 * 2 + 2 * 10));
        QCOMPARE(f.emitterTriangles, 2);
        QVERIFY(f.hasDiffuse && !f.hasGlossy && !f.hasSpecular() && !f.hasDeltaLights());
        // The light faces down into the box (its front face is where it emits).
        const TriangleMesh& light = *s.objects[0].worldMesh;
        const V3d n = (light.vertices[1] - light.vertices[0]).cross(light.vertices[2] - light.vertices[0]);
        QVERIFY(n.y < 0);
    }
    QCOMPARE(readText(kResources + "/scenes/cornell-box.json"), readText(kShared + "/scenes/cornell-box.json"));
}

void TestSceneIo::loadsInterior() {
    LoadReport report;
    const Scene s = loadScene(kResources + "/scenes/interior.json", &report);
    QCOMPARE(s.metersPerUnit, 1.0);
    QCOMPARE(s.camera.width, 640);
    QCOMPARE(s.camera.height, 480);
    QVERIFY(report.warnings.empty());
    const SceneFeatures f = analyseFeatures(s);
    QVERIFY(f.hasDiffuse && f.hasGlossy && !f.hasSpecular());
    QCOMPARE(f.pointLights, 1);  // the pendant
    QCOMPARE(f.spotLights, 6);   // four downlights, the table lamp, the shelf wash
    QCOMPARE(f.emitterTriangles, 0);
    // A room of 6 x 3 x 4.5 m: the camera, the lights and every vertex are inside it.
    const auto inside = [](const V3d& p) {
        return p.x >= -1e-9 && p.x <= 6 + 1e-9 && p.y >= -1e-9 && p.y <= 3 + 1e-9 && p.z >= -1e-9 && p.z <= 4.5 + 1e-9;
    };
    QVERIFY(inside(s.camera.position));
    for (const Light& l : s.lights) QVERIFY2(inside(l.position), l.name.c_str());
    for (const Object& o : s.objects)
        for (const V3d& v : o.worldMesh->vertices) QVERIFY2(inside(v), o.name.c_str());
    // Every box stands on something: its lowest point is on the floor or above it.
    const Object* top = nullptr;
    for (const Object& o : s.objects) if (o.name == "table_top") top = &o;
    QVERIFY(top);
    double lowest = 1e9;
    for (const V3d& v : top->worldMesh->vertices) lowest = std::min(lowest, v.y);
    QVERIFY(std::abs(lowest - 0.73) < 1e-12);
}

void TestSceneIo::roundTrips_data() {
    QTest::addColumn<QString>("path");
    QTest::newRow("resources/cornell-box") << QString::fromStdString(kResources + "/scenes/cornell-box.json");
    QTest::newRow("resources/interior") << QString::fromStdString(kResources + "/scenes/interior.json");
    QTest::newRow("shared/cornell-box") << QString::fromStdString(kShared + "/scenes/cornell-box.json");
    QTest::newRow("every key") << QString::fromStdString(kData + "/every-key.json");
}

void TestSceneIo::roundTrips() {
    QFETCH(QString, path);
    const Scene s = loadScene(path.toStdString());
    const std::string text = saveSceneToString(s);
    const Scene back = parseScene(text, path.toStdString());
    QVERIFY(back == s);
    QCOMPARE(back.metersPerUnitGiven, s.metersPerUnitGiven);
    for (size_t i = 0; i < s.objects.size(); ++i) QVERIFY(*back.objects[i].worldMesh == *s.objects[i].worldMesh);
    QCOMPARE(saveSceneToString(back), text);  // stable: a second save changes nothing
}

void TestSceneIo::roundTripsAwkwardNumbers() {
    Scene s = loadScene(kData + "/every-key.json");
    s.camera.position = V3d(0.1 + 0.2, 1.0 / 3.0, -2e-308);
    s.camera.fovYDeg = std::nextafter(40.0, 41.0);
    s.metersPerUnit = 5e-324;
    s.materials[4].radiance = Rgbd(1e300, DBL_MAX, 4.9406564584124654e-324);
    s.materials[0].albedo = Rgbd(std::nextafter(1.0, 0.0), 0.1, 1e-17);
    s.objects[0].name = "quote \" backslash \\ tab \t newline \n nul " + std::string(1, '\0') + " end";
    s.objects[0].mesh.inlineMesh.vertices[4] = V3d(-0.0, 123456789.123456789, 1e30);
    s.lights[1].coneAngleDeg = 90.00000000000001;
    const Scene back = parseScene(saveSceneToString(s), kData + "/every-key.json");
    QVERIFY(back == s);
    QCOMPARE(back.objects[0].name.size(), s.objects[0].name.size());
    QVERIFY(std::signbit(back.objects[0].mesh.inlineMesh.vertices[4].x));
}

// "group" and "on" on every light type: read, written back only where they say something (a
// light on and in no group is written as before), and read back equal.
void TestSceneIo::roundTripsGroupsAndSwitches() {
    Parts p;
    p.lights = light(R"({"name": "a", "type": "point", "position": [0, 2, 0], "lumens": 800, "group": "hall"}, )"
                     R"({"name": "b", "type": "spot", "position": [1, 2, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1], "cone_angle": 30, "group": "hall", "on": false}, )"
                     R"({"name": "c", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1], "on": true}, )"
                     R"({"name": "d", "type": "luminaire", "file": "../../resources/scenes/luminaires/downlight.ies", "position": [0, 2, 1], "direction": [0, -1, 0], "group": "north hall, row 2", "on": false}, )"
                     R"({"name": "e", "type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1]})");
    const Scene s = parseScene(p.text(), kCase);
    QCOMPARE(s.lights[0].group, std::string("hall"));
    QVERIFY(s.lights[0].on);
    QCOMPARE(s.lights[1].group, std::string("hall"));
    QVERIFY(!s.lights[1].on);
    QVERIFY(s.lights[2].group.empty() && s.lights[2].on);
    QCOMPARE(s.lights[3].group, std::string("north hall, row 2"));
    QVERIFY(!s.lights[3].on);
    QVERIFY(s.lights[4].group.empty() && s.lights[4].on);
    const std::string text = saveSceneToString(s);
    QVERIFY(text.find(R"("lumens": 800, "group": "hall"})") != std::string::npos);
    QVERIFY(text.find(R"("cone_angle": 30, "group": "hall", "on": false})") != std::string::npos);
    QVERIFY(text.find(R"("name": "c", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]})") != std::string::npos);
    QVERIFY(text.find(R"("group": "north hall, row 2", "on": false})") != std::string::npos);
    const std::string last = "\"position\": [0, 1, 0], \"intensity\": [1, 1, 1]}\n  ]";
    QVERIFY(text.find(last) != std::string::npos);  // e: no group, on: nothing added
    const Scene back = parseScene(text, kCase);
    QVERIFY(back == s);
    QCOMPARE(saveSceneToString(back), text);
    // Groups are their own namespace: a group may be named as a light is.
    Parts same;
    same.lights = light(R"({"name": "bulb", "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1], "group": "bulb"})");
    QCOMPARE(parseScene(same.text(), kCase).lights[0].group, std::string("bulb"));
}

void TestSceneIo::savesAtomically() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const Scene s = loadScene(kData + "/every-key.json");
    const std::string path = dir.filePath("copy.json").toStdString();
    QFile old(QString::fromStdString(path));
    QVERIFY(old.open(QIODevice::WriteOnly));
    old.write("old contents");
    old.close();
    saveScene(s, path);
    QCOMPARE(readText(path), saveSceneToString(s));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"copy.json"});  // no temporary left

    const std::string nowhere = dir.filePath("missing-folder/scene.json").toStdString();
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, saveScene(s, nowhere));
    QVERIFY(!QFile::exists(QString::fromStdString(nowhere)));

    // A file that cannot be replaced keeps its contents.
    QVERIFY(QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner));
    if (::geteuid() != 0) {
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, saveScene(Scene(), path));
        QCOMPARE(readText(path), saveSceneToString(s));
    }
    QVERIFY(QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner));
}

void TestSceneIo::appliesTransforms() {
    const auto place = [](const std::string& transform) {
        Parts p;
        p.objects = meshObject(R"({"vertices": [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]], "triangles": [[0, 1, 2], [2, 1, 0]]})",
                               R"(, "transform": )" + transform);
        return parseScene(p.text(), kCase).objects[0];
    };
    // Scale 2, then 90 degrees about +z (right hand: x -> y), then translate.
    Object o = place(R"({"scale": 2, "rotate": [0, 0, 1, 90], "translate": [10, 0, 0]})");
    QCOMPARE(o.worldMesh->vertices[0], V3d(10, 2, 0));
    QCOMPARE(o.worldMesh->vertices[1], V3d(8, 0, 0));
    QCOMPARE(o.worldMesh->vertices[3], V3d(8, 2, 2));
    QVERIFY(o.transform->uniformScale);

    // Non-uniform scale then 90 degrees about +y (z -> x, x -> -z): (1,1,1) -> (1,2,3) -> (3,2,-1).
    o = place(R"({"scale": [1, 2, 3], "rotate": [0, 5, 0, 90]})");
    QCOMPARE(o.worldMesh->vertices[3], V3d(3, 2, -1));
    QVERIFY(!o.transform->uniformScale);

    // 120 degrees about (1,1,1) cycles the axes; the angle is not exact, so compare closely.
    o = place(R"({"rotate": [1, 1, 1, 120]})");
    QVERIFY(near(o.worldMesh->vertices[0], V3d(0, 1, 0)));
    QVERIFY(near(o.worldMesh->vertices[1], V3d(0, 0, 1)));
    o = place(R"({"rotate": [0, 0, 1, 30], "translate": [0, 0, 5]})");
    QVERIFY(near(o.worldMesh->vertices[0], V3d(std::sqrt(3.0) / 2, 0.5, 5)));

    // Row-major matrix acting on column vectors: translation in the last column.
    o = place(R"({"matrix": [0, -1, 0, 5, 1, 0, 0, 6, 0, 0, 2, 7, 0, 0, 0, 1]})");
    QCOMPARE(o.worldMesh->vertices[3], V3d(4, 7, 9));
    QCOMPARE(o.worldMesh->vertices[0], V3d(5, 7, 7));
    QCOMPARE(o.transform->toMatrix()[0][3], 5.0);

    // toMatrix of the TRS form is the same map.
    o = place(R"({"scale": [1, 2, 3], "rotate": [0, 1, 0, 90], "translate": [1, 1, 1]})");
    const M44d m = o.transform->toMatrix();
    QCOMPARE(m[0][2], 3.0);   // z scaled by 3 lands on x
    QCOMPARE(m[2][0], -1.0);  // x lands on -z
    QCOMPARE(m[1][3], 1.0);
    QCOMPARE(m[3][3], 1.0);

    // A mirroring scale keeps the index order: the front face follows the transformed vertices.
    o = place(R"({"scale": [-1, 1, 1]})");
    QCOMPARE(o.worldMesh->triangles, (std::vector<V3i>{V3i(0, 1, 2), V3i(2, 1, 0)}));
    QCOMPARE(o.worldMesh->vertices[0], V3d(-1, 0, 0));

    // A quad becomes (v0,v1,v2), (v0,v2,v3) and moves with its transform.
    Parts p;
    p.objects = meshObject(R"({"quad": [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]]})", R"(, "transform": {"translate": [0, 3, 0]})");
    const Scene s = parseScene(p.text(), kCase);
    QCOMPARE(s.objects[0].worldMesh->triangles, (std::vector<V3i>{V3i(0, 1, 2), V3i(0, 2, 3)}));
    QCOMPARE(s.objects[0].worldMesh->vertices[2], V3d(1, 3, 1));
}

void TestSceneIo::analysesFeatures() {
    const Scene s = loadScene(kData + "/every-key.json");
    const SceneFeatures f = analyseFeatures(s);
    QVERIFY(f.hasDiffuse && f.hasGlossy && f.hasMirror && f.hasDielectric && f.hasSpecular());
    QCOMPARE(f.emitterTriangles, 2);
    QCOMPARE(f.pointLights, 1);
    QCOMPARE(f.spotLights, 2);
    QCOMPARE(f.directionalLights, 1);
    QCOMPARE(f.triangles, size_t(2 + 2 + 6 + 4 + 4 + 12 + 4 + 4));
    QCOMPARE(s.materialIndex("chrome"), 2);
    QCOMPARE(s.materialIndex("gold"), -1);
    QCOMPARE(s.findMaterial("spare lamp")->type, MaterialType::Emitter);
    QVERIFY(s.findMaterial("gold") == nullptr);

    // Types used only by materials that no object uses do not count.
    Scene diffuseOnly = s;
    for (Object& o : diffuseOnly.objects) o.material = "matte";
    const SceneFeatures g = analyseFeatures(diffuseOnly);
    QVERIFY(g.hasDiffuse && !g.hasGlossy && !g.hasMirror && !g.hasDielectric);
    QCOMPARE(g.emitterTriangles, 0);
}

QTEST_GUILESS_MAIN(TestSceneIo)
#include "test_scene_io.moc"
