#pragma once
// Reading and writing SPEC.md scene files (version 1).

#include "core/scene/scene.h"

#include <stdexcept>
#include <string>

namespace lucerna {

// A scene that breaks the contract. what() is the one line SPEC.md asks for:
// "<file>: <place>: <problem>", the place a JSON path such as objects[2].mesh.vertices[5][1]
// (or "line N" where the JSON itself does not parse).
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct LoadReport {
    int degenerateTrianglesDropped = 0;  // zero-area triangles removed, over all objects
    std::vector<std::string> warnings;   // one line each, ready to print
};

// Parses and validates a scene file, loads its mesh files and resolves world-space meshes.
// Throws SceneError on any violation of SPEC.md section 1; never crashes on any input bytes.
Scene loadScene(const std::string& path, LoadReport* report = nullptr);

// The same, from bytes already in memory; `path` names the file in messages and gives the folder
// that relative mesh paths resolve against.
Scene parseScene(const std::string& bytes, const std::string& path, LoadReport* report = nullptr);

// Serialises to SPEC.md JSON such that parseScene(saveSceneToString(s)) == s.
std::string saveSceneToString(const Scene& scene);

// Writes atomically (temporary file in the same folder, then rename). Throws std::runtime_error.
void saveScene(const Scene& scene, const std::string& path);

// Recomputes Object::worldMesh for every object (after an edit of a transform or a mesh).
// Mesh files are read relative to scene.baseDir. Throws SceneError.
void resolveMeshes(Scene& scene, LoadReport* report = nullptr);

}  // namespace lucerna
