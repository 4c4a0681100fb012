#pragma once
// Model import (README, "Import Model"): OBJ with its MTL, glTF 2.0 (.gltf, .glb) with
// KHR_lights_punctual, FBX, COLLADA and the other formats Assimp reads, turned into SPEC.md
// objects (inline world-space triangle meshes), materials and lights, with a report of what was
// mapped and what was approximated. Assimp is confined to model_import.cpp.

#include "core/scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct ImportOptions {
    // The scene's unit: coordinates in metres are divided by this.
    double sceneMetersPerUnit = 1.0;
    // The model's unit in metres for formats that state none (OBJ, STL, PLY, ...): metres when
    // absent. Formats with a unit (glTF: metres; COLLADA <unit>; FBX UnitScaleFactor) use theirs.
    std::optional<double> fileMetersPerUnit;
    // When given, names are made unique against this scene too (objects and lights together,
    // materials apart), as SPEC.md requires of the scene the import is added to.
    const Scene* into = nullptr;
};

struct ModelImport {
    // One object per mesh instance and material (an OBJ `usemtl` group, a glTF primitive), each
    // an Inline mesh already in world space (node transforms and the unit applied, no transform
    // key). worldMesh is left empty: the caller resolves it (the loader's rules) in its scene.
    std::vector<Object> objects;
    std::vector<Material> materials;  // those the objects use, once each
    std::vector<Light> lights;
    size_t triangles = 0;
    // One line each: the summary first, then what was approximated or ignored.
    std::vector<std::string> report;
};

// Reads the model at `path`. Throws std::runtime_error with one line (the file and Assimp's
// message) when the file cannot be read or holds no triangles and no lights.
ModelImport importModel(const std::string& path, const ImportOptions& options = {});

}  // namespace lucerna
