#pragma once
// File > Import mesh: a mesh file (OBJ, PLY, OFF, STL, as the scene loader reads them) becomes a
// new object with a diffuse material of its own.

#include "ui/document/document.h"

#include <QString>

namespace lucerna {

struct MeshImport {
    Object object;      // with its resolved world mesh
    Material material;  // diffuse, light grey
};

// `file` as a scene file stores a path: relative to the scene's folder when the scene has a
// file, absolute for an untitled scene.
std::string scenePathOf(const Document& doc, const QString& file);

// The object for `file`: named after the file (unique among objects and lights), the path
// relative to the scene's folder when the scene has a file, absolute for an untitled scene. A
// mesh already within the scene's size range keeps its coordinates; one far smaller or larger
// (a unit-sized model in a millimetre scene) is scaled uniformly so that its largest side is a
// third of the scene's, and stood on the scene's lowest point at its middle.
// Throws std::runtime_error with a one-line reason when the file cannot be used.
MeshImport importMesh(const Document& doc, const QString& file);

}  // namespace lucerna
