#pragma once
// Small geometric facts about a scene that the editor needs: its bounds, which object a traced
// triangle belongs to, and the world mesh of one object after an edit of its transform.

#include "core/scene/scene.h"

#include <QString>

#include <optional>

namespace lucerna {

struct SceneBounds {
    V3d lo{0, 0, 0}, hi{1, 1, 1}, center{0.5, 0.5, 0.5};
    double radius = 1;
};
// Bounds of all world meshes and the positions of lights that have one (not directional lights
// or suns, at infinity); a unit box when the scene is empty.
SceneBounds sceneBounds(const Scene& scene);
// The floor area the report and the lighting energy take by default: the extent in plan (x by z,
// y up) of sceneBounds, in m² (through meters_per_unit).
double planAreaM2(const Scene& scene);

// `object` with its worldMesh recomputed (transform or mesh edited). Mesh files are read relative
// to scene.baseDir; the object's material must be one of scene's. Throws SceneError with a
// one-line reason.
Object resolvedObject(const Scene& scene, Object object);

// "mm", "m", ... for lengths in scene units (from meters_per_unit), or "units".
QString lengthUnit(const Scene& scene);

}  // namespace lucerna
