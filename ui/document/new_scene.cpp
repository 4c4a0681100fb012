#include "ui/document/new_scene.h"

#include "core/scene/scene_geometry.h"
#include "core/photometry/light_output.h"
#include "core/scene/scene_io.h"
#include "ui/io/model_import_action.h"
#include "render/trace/room_camera.h"

#include <QFileInfo>
#include <QObject>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace lucerna {

Scene newSceneWithFloor(const std::string& folder) {
    // Written as a scene file would be, so that it is a scene the loader accepts in every way.
    static const char* const kJson = R"({
  "lucerna": 1,
  "meters_per_unit": 1,
  "camera": {"position": [0, 1.6, 6], "target": [0, 0.4, 0], "up": [0, 1, 0], "fov_y": 50, "resolution": [640, 480]},
  "materials": {"floor": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]}},
  "objects": [
    {"name": "floor", "material": "floor", "mesh": {"quad": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5], [5, 0, -5]]}}
  ],
  "lights": [
    {"name": "point", "type": "point", "position": [0, 2.5, 0], "lumens": 3000, "temperature": 3000}
  ]
})";
    return parseScene(kJson, (std::filesystem::path(folder) / "untitled.json").string());
}

bool isNewScenesFloor(const Object& object) {
    return object == newSceneWithFloor(".").objects.front();
}

void arrangeAroundModel(Scene& scene, size_t firstModelObject, size_t modelLights) {
    V3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (size_t i = firstModelObject; i < scene.objects.size(); ++i)
        if (const auto& mesh = scene.objects[i].worldMesh)
            for (const V3d& v : mesh->vertices) {
                lo = V3d(std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z));
                hi = V3d(std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z));
            }
    // The new scene's light is the first; the model's follow it.
    const bool keepOwnLight = modelLights == 0;
    if (!keepOwnLight && !scene.lights.empty()) scene.lights.erase(scene.lights.begin());
    if (lo.x > hi.x) return;  // no geometry: the floor scene as it is
    const V3d centre = (lo + hi) * 0.5;
    const double radius = std::max((hi - lo).length() * 0.5, 1e-6);
    const double metre = 1.0 / scene.metersPerUnit;

    Object& floor = scene.objects.front();
    const double half = std::max(2.0 * radius, 5.0 * metre);
    floor.mesh.quad = {V3d(centre.x - half, lo.y, centre.z - half), V3d(centre.x - half, lo.y, centre.z + half),
                       V3d(centre.x + half, lo.y, centre.z + half), V3d(centre.x + half, lo.y, centre.z - half)};
    floor = resolvedObject(scene, floor);

    if (keepOwnLight && !scene.lights.empty()) {
        Light& light = scene.lights.front();
        const V3d before = light.position;
        light.position = V3d(centre.x, hi.y + radius, centre.z);
        // As bright on the model's top as the new scene's light is on its floor.
        const double ratio = (light.position.y - lo.y) / std::max(before.y, 1e-9) * scene.metersPerUnit;
        PhotometricSpec output = photometricOf(light);
        output.value *= ratio * ratio;
        light = withPhotometric(light, output);
    }
    Camera& camera = scene.camera;
    camera.target = centre;
    camera.up = V3d(0, 1, 0);
    camera.position = centre + V3d(0.45, 0.35, 1.0).normalized() * (1.1 * radius / std::sin(camera.fovYDeg * M_PI / 360.0));
}

Scene newSceneWithModel(const QString& path, QStringList* report) {
    Scene scene = newSceneWithFloor(QFileInfo(path).absolutePath().toStdString());
    // Prepared against the new scene (its unit, its names), then added to it.
    PreparedImport imported = prepareModelImport(Document(Scene(scene)), path);
    if (report) *report = imported.report;
    const size_t firstModelObject = scene.objects.size();
    scene.objects.insert(scene.objects.end(), imported.objects.begin(), imported.objects.end());
    scene.materials.insert(scene.materials.end(), imported.materials.begin(), imported.materials.end());
    scene.lights.insert(scene.lights.end(), imported.lights.begin(), imported.lights.end());
    arrangeAroundModel(scene, firstModelObject, imported.lights.size());
    // A building is seen from inside its largest room; anything else stays framed from outside.
    if (const auto camera = cameraInLargestRoom(scene, scene.camera)) {
        scene.camera = *camera;
        if (report)
            *report << QObject::tr("camera placed in the largest room at eye height, at (%1, %2, %3)")
                           .arg(camera->position.x, 0, 'g', 5)
                           .arg(camera->position.y, 0, 'g', 5)
                           .arg(camera->position.z, 0, 'g', 5);
    }
    return scene;
}

}  // namespace lucerna
