// `--backend auto` (render/progressive/auto_backend.cpp): different scenes get the backends their
// light transport needs, each with a one-line reason.

#include "core/scene_io.h"
#include "render/progressive/backend.h"

#include <QtTest>

using namespace lucerna;

namespace {

const std::string kResources = LUCERNA_RESOURCE_DIR;

// A closed room whose only light is an emitter facing the ceiling: everything below it is lit
// only by the ceiling's bounce. `extra` adds objects and materials.
std::string indirectRoom(const std::string& extraMaterials = "", const std::string& extraObjects = "") {
    return R"({"lucerna": 1,
  "camera": {"position": [0, 2.5, -1.9], "target": [0, 0, 0.5], "fov_y": 60, "resolution": [64, 48]},
  "materials": {"white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]},
                "lamp": {"type": "emitter", "radiance": [20, 20, 20]})" + extraMaterials + R"(},
  "objects": [
    {"name": "floor", "material": "white", "mesh": {"quad": [[-2,0,-2],[-2,0,2],[2,0,2],[2,0,-2]]}},
    {"name": "ceiling", "material": "white", "mesh": {"quad": [[-2,3,-2],[2,3,-2],[2,3,2],[-2,3,2]]}},
    {"name": "wall_n", "material": "white", "mesh": {"quad": [[-2,0,2],[-2,3,2],[2,3,2],[2,0,2]]}},
    {"name": "wall_s", "material": "white", "mesh": {"quad": [[-2,0,-2],[2,0,-2],[2,3,-2],[-2,3,-2]]}},
    {"name": "wall_e", "material": "white", "mesh": {"quad": [[2,0,-2],[2,0,2],[2,3,2],[2,3,-2]]}},
    {"name": "wall_w", "material": "white", "mesh": {"quad": [[-2,0,-2],[-2,3,-2],[-2,3,2],[-2,0,2]]}},
    {"name": "uplight", "material": "lamp", "mesh": {"quad": [[-0.2,1,-0.2],[-0.2,1,0.2],[0.2,1,0.2],[0.2,1,-0.2]]}})" +
           extraObjects + "]}";
}

AutoChoice choose(const std::string& json) { return chooseAutoBackend(parseScene(json, "auto.json")); }

}  // namespace

class TestAutoBackend : public QObject {
    Q_OBJECT
private slots:
    void bundledScenes();
    void indirectlyLitRoom();
    void noLight();
};

void TestAutoBackend::bundledScenes() {
    // The issue's pair: a diffuse/glossy interior lit directly, and a caustic scene.
    const AutoChoice interior = chooseAutoBackend(loadScene(kResources + "/scenes/interior.json"));
    const AutoChoice caustics = chooseAutoBackend(loadScene(kResources + "/scenes/caustics.json"));
    const AutoChoice cornell = chooseAutoBackend(loadScene(kResources + "/scenes/cornell-box.json"));
    qInfo("interior: %s", interior.reason.c_str());
    qInfo("caustics: %s", caustics.reason.c_str());
    qInfo("cornell: %s", cornell.reason.c_str());
    QCOMPARE(interior.backend, std::string("path"));
    QCOMPARE(caustics.backend, std::string("bdpt"));
    QCOMPARE(cornell.backend, std::string("path"));
    for (const AutoChoice* c : {&interior, &caustics, &cornell}) {
        QVERIFY(findBackend(c->backend) != nullptr);
        QVERIFY(c->reason.starts_with(c->backend + ": "));
        QVERIFY(c->reason.find('\n') == std::string::npos);
    }
}

void TestAutoBackend::indirectlyLitRoom() {
    const AutoChoice diffuse = choose(indirectRoom());
    qInfo("%s", diffuse.reason.c_str());
    QCOMPARE(diffuse.backend, std::string("cmlt"));
    QVERIFY(diffuse.reason.find("indirectly") != std::string::npos);
    const AutoChoice withMirror = choose(indirectRoom(R"(, "chrome": {"type": "mirror", "reflectance": [0.9, 0.9, 0.9]})",
                                                      R"(, {"name": "mirror", "material": "chrome", "mesh": {"quad": [[1,0.2,1.9],[1,1.5,1.9],[1.8,1.5,1.9],[1.8,0.2,1.9]]}})"));
    qInfo("%s", withMirror.reason.c_str());
    QCOMPARE(withMirror.backend, std::string("bdpt"));
    QVERIFY(withMirror.reason.find("caustics") != std::string::npos);
}

void TestAutoBackend::noLight() {
    const std::string dark = R"({"lucerna": 1, "camera": {"position": [0, 1, -3], "target": [0, 0, 0], "fov_y": 40, "resolution": [8, 8]},
      "materials": {"white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]}},
      "objects": [{"name": "floor", "material": "white", "mesh": {"quad": [[-2,0,-2],[-2,0,2],[2,0,2],[2,0,-2]]}}]})";
    const AutoChoice c = choose(dark);
    QCOMPARE(c.backend, std::string("path"));
    QVERIFY(c.reason.find("no light") != std::string::npos);
}

QTEST_GUILESS_MAIN(TestAutoBackend)
#include "test_auto_backend.moc"
