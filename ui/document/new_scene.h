#pragma once
// File > New: the scene a new document starts from.

#include "core/scene/scene.h"

#include <QString>
#include <QStringList>

#include <string>

namespace lucerna {

// An empty room's floor: a 10 m x 10 m light grey square at y = 0 (metres), a camera at eye height
// looking at its middle, and one point light 2.5 m above it so that the preview shows something.
// Untitled: relative mesh paths would resolve against `folder` (the user's documents folder).
Scene newSceneWithFloor(const std::string& folder);
// Whether `object` is that floor as File > New made it (its name, material and square, untouched
// and in no room): what a room whose floor lies on it replaces (README, "Rooms").
bool isNewScenesFloor(const Object& object);

// File > Import Model into a new scene: `scene` is newSceneWithFloor's with a model's objects
// (from `firstModelObject` on, world meshes resolved) and lights added. The floor moves under
// the model and grows to twice its size, the camera frames it from the front-right and above,
// and the new scene's own light stays (moved above the model) only when the model brought none.
void arrangeAroundModel(Scene& scene, size_t firstModelObject, size_t modelLights);

// newSceneWithFloor's scene with the model at `path` (ui/io/model_import_action.h) arranged in it by
// arrangeAroundModel; `report` gets the import's report. Throws std::runtime_error with one line.
Scene newSceneWithModel(const QString& path, QStringList* report);

}  // namespace lucerna
