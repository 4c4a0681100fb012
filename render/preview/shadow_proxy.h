#pragma once
// A coarse stand-in for the scene in the low-resolution shadow maps of the VPLs and area-light
// samples, which are drawn again for every fresh VPL set: their cost is (maps x triangles), so a
// model of a million triangles would cost a million triangles per VPL per set. Vertex clustering
// (Rossignac and Borrel 1993): vertices snap to the mean of their grid cell, triangles that
// collapse go, duplicates go. Robust on any triangle soup (imported models are rarely manifold,
// which quadric decimation needs), linear in the triangle count, and its error is bounded by
// the cell: the shadow lookups add that bound to their bias (ShadowCaster::slack).

#include <cstddef>
#include <vector>

namespace lucerna::preview_detail {

struct ShadowProxy {
    std::vector<float> positions;  // xyz per vertex, three vertices per triangle
    float cellSize = 0;            // 0: the input itself (it had no more than maxTriangles)
};

// At most maxTriangles triangles standing for `positions` (xyz per vertex of non-indexed
// triangles): the input itself when it is small enough, else the clustering on the finest grid
// (cubic cells over the bounding box) that meets the budget. Every proxy vertex lies within
// cellSize * sqrt(3) of an input vertex of its cell.
ShadowProxy clusterTriangles(const std::vector<float>& positions, size_t maxTriangles);

}  // namespace lucerna::preview_detail
