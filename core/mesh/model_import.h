#pragma once
// Model import (README, "Import Model"): OBJ with its MTL, glTF 2.0 (.gltf, .glb) with
// KHR_lights_punctual, FBX, COLLADA and the other formats Assimp reads, turned into SPEC.md
// objects (inline world-space triangle meshes), materials and lights, with a report of what was
// mapped and what was approximated. Assimp is confined to model_import.cpp, and it runs in a
// process of its own (model_import_process.cpp): Assimp 5.2's importers have known crashes on
// malformed files, and a crash there must not take the application, or its unsaved work, down.

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

// Reads the model at `path` in the importer's own process (the executable lucerna-model-import,
// beside this one or where the build put it). Throws std::runtime_error with one line (the file
// and Assimp's message) when the file cannot be read or holds no triangles and no lights, and
// when the importer crashed on it or could not be started.
ModelImport importModel(const std::string& path, const ImportOptions& options = {});

// The same in this process: what the importer's process runs. A malformed file may crash it.
ModelImport importModelInProcess(const std::string& path, const ImportOptions& options = {});

// The importer process's main: `lucerna-model-import REQUEST.json FOLDER` reads the request that
// importModel wrote and writes the result into FOLDER. Returns 0, or 2 after one line on stderr.
int runModelImportProcess(int argc, char** argv);

}  // namespace lucerna
