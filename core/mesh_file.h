#pragma once
// OBJ, PLY, OFF and STL files through OpenMesh: positions and faces only (SPEC.md ignores normals,
// UVs, colours and materials); polygons fan-triangulated from their first vertex in file order.

#include "core/scene.h"

#include <string>

namespace lucerna {

// Throws std::runtime_error with a one-line reason if the file is missing, unreadable or not a
// mesh OpenMesh understands.
TriangleMesh readMeshFile(const std::string& absolutePath);

}  // namespace lucerna
