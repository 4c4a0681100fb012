#pragma once
// The parts of mesh reading that cannot be left to OpenMesh, whose readers trust what a file
// claims: a face line "3000000000 0 1 2" makes its OFF reader push three billion vertex handles,
// a binary PLY list count of 2^31-1 (or -1) makes its PLY reader do the same, and a face cut
// short is padded with index 0. So PLY and OFF files are read here, each value checked against
// the bytes that are really there (work and memory grow with the file, not with its claims), and
// OBJ files are checked here before OpenMesh reads them.
//
// Values are what OpenMesh made of them, so that meshes and renders stay the same: positions go
// through single precision (a PLY file's doubles too), every polygon of three or more vertices
// is kept in file order, shorter ones are skipped.
//
// Each function throws std::runtime_error with a one-line reason that does not name the file
// (readMeshFile puts the path in front).

#include "core/scene/scene.h"

#include <string>

namespace lucerna {

// The whole content of a PLY file (ASCII or binary, either byte order) whose header has passed
// readMeshFile's checks.
TriangleMesh readPlyBytes(const std::string& bytes);

// The whole content of an OFF file: ASCII ([ST][C][N]OFF, '#' comments) or OpenMesh's binary
// form ("OFF BINARY", little-endian 32-bit counts, floats and indices).
TriangleMesh readOffBytes(const std::string& bytes);

// Problems with an OBJ file that OpenMesh would hide: a vertex line whose coordinates are not
// numbers, not finite or beyond single precision (OpenMesh drops the vertex, and the faces then
// refer to vertices that do not exist), and a material library (mtllib, resolved against
// `folder`) that is not a regular file (OpenMesh would read it forever). Empty when none.
std::string objProblem(const std::string& bytes, const std::string& folder);

}  // namespace lucerna
