#pragma once
// What the scene-file tests share (test_scene_io, test_mesh_files): small scene texts built part
// by part, the message a text is rejected with, and readable QCOMPARE failures for vectors.

#include "core/scene/scene_io.h"

#include <QFile>
#include <QString>
#include <QtTest>

#include <string>

namespace lucerna::test {

inline const std::string kData = LUCERNA_TEST_DATA_DIR;
inline const std::string kShared = LUCERNA_SHARED_DIR;
inline const std::string kResources = LUCERNA_RESOURCE_DIR;
// Scenes parsed from memory are named as if they lay in tests/data, so "meshes/..." resolves.
inline const std::string kCase = kData + "/case.json";

// A small valid scene, one part per line so that syntax errors have predictable line numbers:
// line 2 lucerna, 3 camera, 4 materials, 5 objects, 6 lights.
struct Parts {
    std::string lucerna = R"("lucerna": 1)";
    std::string camera = R"("camera": {"position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [64, 48]})";
    std::string materials = R"("materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}, )"
                            R"("lamp": {"type": "emitter", "radiance": [1, 1, 1]}})";
    std::string objects = R"("objects": [{"name": "floor", "material": "white", )"
                          R"("mesh": {"quad": [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]}}])";
    std::string lights = R"("lights": [{"name": "bulb", "type": "point", "position": [0, 2, 0], "intensity": [1, 1, 1]}])";

    // Empty parts are left out (with their lines, so a missing camera shifts what follows).
    std::string text() const {
        std::string out = "{";
        for (const std::string* part : {&lucerna, &camera, &materials, &objects, &lights})
            if (!part->empty()) out += (out.size() > 1 ? ",\n" : "\n") + *part;
        return out + "\n}\n";
    }
};

inline std::string camera(const std::string& inner) { return R"("camera": {)" + inner + "}"; }
inline std::string cameraWith(const std::string& extra) {
    return camera(R"("position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [64, 48])" + extra);
}
inline std::string material(const std::string& body) { return R"("materials": {"white": )" + body + "}"; }
inline std::string object(const std::string& body) { return R"("objects": [)" + body + "]"; }
inline std::string meshObject(const std::string& mesh, const std::string& extra = {}) {
    return object(R"({"name": "thing", "material": "white", "mesh": )" + mesh + extra + "}");
}
inline std::string withTransform(const std::string& transform) {
    return meshObject(R"({"quad": [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]})", R"(, "transform": )" + transform);
}
inline std::string light(const std::string& body) { return R"("lights": [)" + body + "]"; }
inline std::string spot(const std::string& cone) {
    return light(R"({"name": "s", "type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1], )" + cone + "}");
}

// The message of the SceneError that `json` raises, or a test failure if it raises none.
inline std::string rejection(const std::string& json, const std::string& path = kCase) {
    try {
        parseScene(json, path);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(accepted)";
}

inline std::string readText(const std::string& path) {
    QFile f(QString::fromStdString(path));
    if (!f.open(QIODevice::ReadOnly)) return {};
    return f.readAll().toStdString();
}

}  // namespace lucerna::test

// Readable QCOMPARE failures for vectors (found by argument-dependent lookup).
namespace IMATH_INTERNAL_NAMESPACE {
inline char* toString(const Vec3<double>& v) { return qstrdup(QString("(%1, %2, %3)").arg(v.x, 0, 'g', 17).arg(v.y, 0, 'g', 17).arg(v.z, 0, 'g', 17).toUtf8()); }
inline char* toString(const Vec3<int>& v) { return qstrdup(QString("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z).toUtf8()); }
}  // namespace IMATH_INTERNAL_NAMESPACE
