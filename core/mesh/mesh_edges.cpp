#include "core/mesh/mesh_edges.h"

#include <algorithm>
#include <map>
#include <tuple>
#include <utility>

namespace lucerna {

size_t boundaryEdgeCount(const TriangleMesh& mesh) {
    // Weld by exact position: a model's copies of one corner carry bit-identical coordinates.
    std::map<std::tuple<double, double, double>, int> ids;
    std::vector<int> welded(mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const V3d& p = mesh.vertices[i];
        welded[i] = ids.try_emplace({p.x, p.y, p.z}, int(ids.size())).first->second;
    }
    std::map<std::pair<int, int>, int> uses;
    const auto inRange = [&](int i) { return i >= 0 && size_t(i) < welded.size(); };
    for (const V3i& t : mesh.triangles) {
        if (!inRange(t.x) || !inRange(t.y) || !inRange(t.z)) continue;
        const int w[3] = {welded[size_t(t.x)], welded[size_t(t.y)], welded[size_t(t.z)]};
        // Two corners in one place: a sliver with no surface, whose two remaining edges coincide.
        if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0]) continue;
        for (int k = 0; k < 3; ++k) ++uses[std::minmax(w[k], w[(k + 1) % 3])];
    }
    return size_t(std::count_if(uses.begin(), uses.end(), [](const auto& e) { return e.second == 1; }));
}

}  // namespace lucerna
