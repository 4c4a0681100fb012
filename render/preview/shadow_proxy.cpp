#include "render/preview/shadow_proxy.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

namespace lucerna::preview_detail {

namespace {

struct Grid {
    float lo[3], cell;
    int cells[3];
    uint64_t key(const float* p) const {
        uint64_t k = 0;
        for (int a = 0; a < 3; ++a) {
            const int i = std::clamp(int((p[a] - lo[a]) / cell), 0, cells[a] - 1);
            k = k * uint64_t(cells[a]) + uint64_t(i);
        }
        return k;
    }
};

struct TriangleKeyHash {
    size_t operator()(const std::array<uint64_t, 3>& t) const {
        return size_t(t[0] * 0x9e3779b97f4a7c15ULL ^ (t[1] + 0x632be59bd9b4e019ULL) * 0xbf58476d1ce4e5b9ULL ^
                      t[2] * 0x94d049bb133111ebULL);
    }
};

// The clustering on one grid: the surviving triangles as cell keys, and each cell's mean vertex.
ShadowProxy clusterOn(const std::vector<float>& positions, const Grid& grid) {
    const size_t vertices = positions.size() / 3;
    std::unordered_map<uint64_t, std::array<double, 4>> sums;  // xyz sum, count
    std::unordered_set<std::array<uint64_t, 3>, TriangleKeyHash> kept;
    std::vector<std::array<uint64_t, 3>> order;  // first-seen order, so the output is deterministic
    for (size_t t = 0; t + 2 < vertices; t += 3) {
        std::array<uint64_t, 3> k{};
        for (int v = 0; v < 3; ++v) {
            const float* p = &positions[(t + size_t(v)) * 3];
            k[size_t(v)] = grid.key(p);
            auto& s = sums[k[size_t(v)]];
            s[0] += p[0], s[1] += p[1], s[2] += p[2], s[3] += 1;
        }
        if (k[0] == k[1] || k[1] == k[2] || k[0] == k[2]) continue;  // collapsed
        // One triangle per cell triple whatever its winding: shadow maps do not cull faces.
        std::array<uint64_t, 3> sorted = k;
        std::sort(sorted.begin(), sorted.end());
        if (kept.insert(sorted).second) order.push_back(k);
    }
    ShadowProxy proxy;
    proxy.cellSize = grid.cell;
    proxy.positions.reserve(order.size() * 9);
    for (const auto& k : order)
        for (uint64_t key : k) {
            const auto& s = sums[key];
            for (int a = 0; a < 3; ++a) proxy.positions.push_back(float(s[size_t(a)] / s[3]));
        }
    return proxy;
}

}  // namespace

ShadowProxy clusterTriangles(const std::vector<float>& positions, size_t maxTriangles) {
    const size_t triangles = positions.size() / 9;
    if (triangles <= maxTriangles || maxTriangles == 0) return {positions, 0.0f};
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (size_t i = 0; i < positions.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], positions[i]);
        hi[i % 3] = std::max(hi[i % 3], positions[i]);
    }
    const float extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-20f});
    // A closed surface spanning k cells a side crosses about 6 k^2 cells and leaves about two
    // triangles per cell: start near that and coarsen until the budget is met.
    double k = std::max(2.0, std::sqrt(double(maxTriangles) / 2.0));
    for (;;) {
        Grid g{};
        g.cell = extent / float(k);
        for (int a = 0; a < 3; ++a) {
            g.lo[a] = lo[a];
            g.cells[a] = std::max(1, int(std::ceil((hi[a] - lo[a]) / g.cell)) + 1);
        }
        ShadowProxy proxy = clusterOn(positions, g);
        if (proxy.positions.size() / 9 <= maxTriangles || k <= 2.0) return proxy;
        k = std::max(2.0, k * 0.8);
    }
}

}  // namespace lucerna::preview_detail
