#pragma once
// STL meshes, binary and ASCII, read here rather than by OpenMesh: its reader builds half-edge
// connectivity as it goes, and a vertex shared by many triangles makes that quadratic (a 2 MB
// binary file of 40000 triangles around one vertex took 21 s, a 10 MB one would take minutes).
//
// The mesh is what OpenMesh made of a valid file, so that meshes and renders stay the same: a
// file is binary when its size is 84 bytes plus 50 for each triangle its header counts, ASCII
// otherwise; each corner's position (single precision) becomes a vertex the first time it is
// met, in file order, and is shared by the later corners at the same position (OpenMesh's test:
// coordinates within FLT_MIN of each other, so 0 and -0 are one); a triangle with two corners on
// one vertex is skipped; normals and attribute bytes are ignored.
//
// ASCII: `solid NAME`, then facets `facet normal X Y Z`, `outer loop`, three `vertex X Y Z`,
// `endloop`, `endfacet`; `endsolid NAME`; keywords in any case, several solids in a row allowed.

#include "core/scene/scene.h"

#include <string>

namespace lucerna {

// The whole content of an STL file. Throws std::runtime_error with a one-line reason that does
// not name the file (readMeshFile puts the path in front): a coordinate that is not a finite
// number in single precision, an ASCII facet out of order or cut short (naming its line), a file
// that is neither.
TriangleMesh readStlBytes(const std::string& bytes);

}  // namespace lucerna
