#pragma once
// OBJ, PLY, OFF and STL files: positions and faces only (SPEC.md ignores normals, UVs, colours
// and materials); polygons fan-triangulated from their first vertex in file order. Each format is
// read by Lucerna itself: PLY and OFF by mesh_file_formats.h, OBJ by obj_file.h, STL by
// stl_file.h (each says why no library reads it).

#include "core/scene/scene.h"

#include <string>

namespace lucerna {

// Throws std::runtime_error with a one-line reason (the path first) if the file is missing,
// unreadable, not a regular file, not a valid mesh of its format, or has no faces.
TriangleMesh readMeshFile(const std::string& absolutePath);

// Writes `mesh` as a binary little-endian PLY file (double vertices, int triangles) that
// readMeshFile reads back with every triangle in order, non-manifold ones included (which
// OpenMesh's own writer, building half-edges first, would drop), and the vertices to float
// precision (OpenMesh's PLY reader goes through floats; the renderer traces in floats too). Whole or not at all
// (atomic_file.h); throws std::runtime_error with a one-line reason.
void writePlyFile(const std::string& path, const TriangleMesh& mesh);

}  // namespace lucerna
