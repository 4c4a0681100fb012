// The backend table (render/engine/backend_table.h): `--backend auto` (auto_backend.cpp) gives
// different scenes the backends their light transport needs, each with a one-line reason; every
// option key the table lists for a backend is one its settings read, and a key none of the
// given backends reads is refused with a one-line message.

#include "core/scene/scene_io.h"
#include "render/engine/backend_table.h"

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
    void listedOptionsAreRead();
    void unknownOptionsAreRefused();
};

void TestAutoBackend::listedOptionsAreRead() {
    // A value no option accepts: a backend that reads the key throws, naming it.
    const SceneSnapshot scene = std::make_shared<const Scene>(loadScene(kResources + "/scenes/cornell-box.json"));
    int checked = 0;
    for (const BackendInfo& b : backendTable()) {
        QVERIFY2(!b.options.empty(), qPrintable(QString::fromUtf8(b.name.data(), qsizetype(b.name.size()))));
        for (std::string_view key : b.options) {
            RenderSettings settings;
            settings.options[std::string(key)] = "?";
            const QString where = QString("%1 %2").arg(QString::fromUtf8(b.name.data(), qsizetype(b.name.size())),
                                                       QString::fromUtf8(key.data(), qsizetype(key.size())));
            try {
                b.make(scene, settings);
                QFAIL(qPrintable(where + ": not read"));
            } catch (const std::invalid_argument& e) {
                QVERIFY2(std::string(e.what()).find(key) != std::string::npos, qPrintable(where + ": " + e.what()));
            }
            ++checked;
        }
    }
    QVERIFY(checked >= 40);
}

void TestAutoBackend::unknownOptionsAreRefused() {
    const BackendInfo* mlt = findBackend("mlt");
    const BackendInfo* cmlt = findBackend("cmlt");
    QVERIFY(mlt && cmlt);
    const std::map<std::string, std::string> lens{{"lens_steps", "3"}}, typo{{"lens_step", "3"}};
    requireKnownOptions(lens, std::span(&cmlt, 1));  // must not throw
    const std::vector<const BackendInfo*> both{mlt, cmlt};
    requireKnownOptions(lens, both);  // one of them reads it
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, requireKnownOptions(lens, std::span(&mlt, 1)));
    try {
        requireKnownOptions(typo, both);
        QFAIL("lens_step accepted");
    } catch (const std::invalid_argument& e) {
        const std::string m = e.what();
        QVERIFY2(m.find("lens_step") != std::string::npos && m.find("lens_steps") != std::string::npos &&
                     m.find('\n') == std::string::npos,
                 m.c_str());
    }
}

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
