#pragma once
// The parts of mesh reading that cannot be left to OpenMesh, whose readers trust what a file
// claims: a face line "3000000000 0 1 2" makes its OFF reader push three billion vertex handles,
// a binary PLY list count of 2^31-1 (or -1) makes its PLY reader do the same, and a face cut
// short is padded with index 0. So PLY and OFF files are read here (OBJ files by obj_file.h),
// each value checked against the bytes that are really there (work and memory grow with the
// file, not with its claims).
//
// Values are what OpenMesh made of them, so that meshes and renders stay the same: positions go
// through single precision (a PLY file's doubles too), every polygon of three or more vertices
// is kept in file order, shorter ones are skipped.
//
// Each function throws std::runtime_error with a one-line reason that does not name the file
// (readMeshFile puts the path in front).

#include "core/scene/scene.h"

#include <optional>
#include <string>
#include <string_view>

namespace lucerna {

// The whole content of a PLY file (ASCII or binary, either byte order) whose header has passed
// readMeshFile's checks.
TriangleMesh readPlyBytes(const std::string& bytes);

// The whole content of an OFF file: ASCII ([ST][C][N]OFF, '#' comments) or OpenMesh's binary
// form ("OFF BINARY", little-endian 32-bit counts, floats and indices).
TriangleMesh readOffBytes(const std::string& bytes);

// A coordinate word of a text mesh file as OpenMesh's readers held it (single precision), or
// nothing, with why in `problem`: not a number, not finite, beyond single-precision range. A
// leading '+' is allowed (istream took it).
std::optional<float> parseCoordinate(std::string_view word, std::string* problem);

// An integer word (a leading '+' allowed), or nothing when it is not one or beyond 64 bits.
std::optional<long long> parseInteger(std::string_view word);

}  // namespace lucerna
