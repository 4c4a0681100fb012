#pragma once
// Wavefront OBJ meshes, read here rather than by a library: OpenMesh's reader trusts its lines
// (a face corner without its vertex index, "f # /5", trips an assertion in it and the process
// aborts), so every line is checked against the bytes that are really there, and work and memory
// grow with the file.
//
// Positions and faces only (SPEC.md). The mesh is what OpenMesh made of a valid file, so that
// meshes and renders stay the same: positions through single precision, vertices in file order,
// each face's polygon in file order with a vertex repeated within it dropped after its first
// corner, polygons of fewer than three distinct vertices skipped, the others fanned from their
// first vertex (as readPlyBytes and readOffBytes do).
//
// Read: `v x y z [w]` (further numbers, such as a vertex colour, are checked and ignored); `vt`
// and `vn` (checked, and counted for relative indices); `f` with v, v/vt, v//vn or v/vt/vn
// corners, whose indices count from 1, or from the end (-1 is the last one read so far); a
// positive index may name an element further down the file (OpenMesh read every vertex first).
// `l` and `p` (line and point elements) add no triangles, but their indices are checked as a
// face's are. `mtllib` names are kept for the caller; `g`, `o`, `s`, `usemtl` and the other
// statements carry nothing for positions and are skipped. '#' starts a comment; a line that ends
// in '\' (outside a comment) goes on on the next line. In these two the format is followed where
// OpenMesh was not: it read a face line on past a '#', and joined no lines.

#include "core/scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace lucerna {

struct ObjMesh {
    TriangleMesh mesh;
    // Each mtllib line's library names as written (from its first word to its last: one file
    // name, or several apart), in file order. Not opened here.
    std::vector<std::string> materialLibraries;
};

// The whole content of an OBJ file. Throws std::runtime_error with a one-line reason that starts
// with "line N: " (the first line of a statement continued with '\') and does not name the file:
// a coordinate that is not a number or beyond single precision, a face corner without a vertex
// index or with an index that is zero, not an integer or names no element of the file, a face of
// fewer than three corners (a comment where a corner should be), a line longer than
// kLongestObjLine bytes.
ObjMesh readObjBytes(std::string_view bytes);

inline constexpr size_t kLongestObjLine = size_t(1) << 20;

}  // namespace lucerna
