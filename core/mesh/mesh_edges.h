#pragma once
// Whether a triangle mesh is an open sheet or a closed surface, from how its edges are shared:
// model import (core/mesh/model_import.cpp) makes a transmissive material on an open sheet a thin
// `glazing` pane and keeps one on a closed mesh a `dielectric` solid.

#include "core/scene/scene.h"

#include <cstddef>

namespace lucerna {

// The number of edges that only one triangle uses: the boundary of an open sheet, 0 for a closed
// surface. Vertices at the same position count as one (a file's vertices are often split where
// normals or texture coordinates change); a triangle with two corners in one place is skipped.
size_t boundaryEdgeCount(const TriangleMesh& mesh);

}  // namespace lucerna
