#include "render/trace/room_camera.h"

#include "render/trace/surface_pick.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace lucerna {

namespace {
constexpr int kLattice = 48;          // points along the longer horizontal side
constexpr double kEyeMeters = 1.6;
constexpr double kWallClearanceMeters = 0.6;

struct Probe {
    bool inside = false;
    V3d eye{0, 0, 0};
    double free[8] = {};  // distance to the wall along each horizontal direction (scene units)
    int room = -1;
};

V3d horizontal(int k) {
    const double a = k * std::numbers::pi / 4;
    return V3d(std::cos(a), 0, std::sin(a));
}
}  // namespace

std::optional<Camera> cameraInLargestRoom(const Scene& scene, const Camera& base) {
    V3d lo(1e300, 1e300, 1e300), hi(-1e300, -1e300, -1e300);
    for (const Object& o : scene.objects)
        if (o.worldMesh)
            for (const V3d& v : o.worldMesh->vertices)
                for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], v[a]), hi[a] = std::max(hi[a], v[a]);
    if (!(lo.x < hi.x && lo.z < hi.z)) return std::nullopt;
    std::unique_ptr<SurfacePicker> picker;
    try {
        picker = std::make_unique<SurfacePicker>(scene);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    const double mpu = scene.metersPerUnit;
    const double eye = kEyeMeters / mpu, clearance = kWallClearanceMeters / mpu;
    const double nudge = 1e-5 * (hi - lo).length();  // off a surface, so that a ray does not find it again
    const double cell = std::max(hi.x - lo.x, hi.z - lo.z) / kLattice;
    const int nx = std::max(1, int(std::ceil((hi.x - lo.x) / cell))), nz = std::max(1, int(std::ceil((hi.z - lo.z) / cell)));

    std::vector<Probe> probes(size_t(nx) * size_t(nz));
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nx; ++i) {
            Probe& p = probes[size_t(j) * size_t(nx) + size_t(i)];
            const double x = lo.x + (i + 0.5) * cell, z = lo.z + (j + 0.5) * cell;
            // The floor under the lowest storey's eye height, then the ceiling above it.
            const auto floor = picker->intersect(V3d(x, lo.y + eye, z), V3d(0, -1, 0));
            if (!floor) continue;
            const double floorY = floor->point.y;
            const auto ceiling = picker->intersect(V3d(x, floorY + nudge, z), V3d(0, 1, 0));
            if (!ceiling || ceiling->distance < eye * 1.05) continue;  // open sky, or under a table
            p.eye = V3d(x, floorY + eye, z);
            p.inside = true;
            for (int k = 0; k < 8 && p.inside; ++k) {
                const auto wall = picker->intersect(p.eye, horizontal(k));
                if (!wall) p.inside = false;
                else p.free[k] = wall->distance;
            }
        }

    // Rooms: inside points joined to their neighbours when nothing stands between them.
    std::vector<int> roomSize;
    for (size_t start = 0; start < probes.size(); ++start) {
        if (!probes[start].inside || probes[start].room >= 0) continue;
        const int room = int(roomSize.size());
        roomSize.push_back(0);
        std::vector<size_t> stack{start};
        probes[start].room = room;
        while (!stack.empty()) {
            const size_t k = stack.back();
            stack.pop_back();
            ++roomSize[size_t(room)];
            const int i = int(k % size_t(nx)), j = int(k / size_t(nx));
            const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
            for (int n = 0; n < 4; ++n) {
                const int a = i + di[n], b = j + dj[n];
                if (a < 0 || b < 0 || a >= nx || b >= nz) continue;
                const size_t m = size_t(b) * size_t(nx) + size_t(a);
                Probe& q = probes[m];
                if (!q.inside || q.room >= 0) continue;
                const V3d step = q.eye - probes[k].eye;
                if (std::abs(step.y) > 0.3 / mpu) continue;  // a step between storeys or levels
                const auto between = picker->intersect(probes[k].eye, step);
                if (between && between->distance < step.length()) continue;
                q.room = room;
                stack.push_back(m);
            }
        }
    }
    if (roomSize.empty()) return std::nullopt;
    const int largest = int(std::max_element(roomSize.begin(), roomSize.end()) - roomSize.begin());

    // As a photographer stands in a corner: the point farthest from the room's centre, clear of
    // the walls, that sees the centre, looking across it (any point of the room if none is clear).
    V3d centre(0, 0, 0);
    for (const Probe& p : probes)
        if (p.room == largest) centre += p.eye;
    centre /= double(roomSize[size_t(largest)]);
    const Probe* best = nullptr;
    double bestDistance = -1;
    for (bool needClearance : {true, false}) {
        for (const Probe& p : probes) {
            if (p.room != largest) continue;
            if (needClearance && *std::min_element(p.free, p.free + 8) < clearance) continue;
            const V3d look = V3d(centre.x, p.eye.y, centre.z) - p.eye;
            const double d = look.length();
            if (d <= bestDistance) continue;
            const auto blocked = picker->intersect(p.eye, look);
            if (blocked && blocked->distance < d) continue;  // a pillar or a bend of the room in between
            best = &p, bestDistance = d;
        }
        if (best) break;
    }
    if (!best || bestDistance <= 0) return std::nullopt;
    Camera c = base;
    c.position = best->eye;
    c.target = V3d(centre.x, best->eye.y, centre.z);
    c.up = V3d(0, 1, 0);
    c.fovYDeg = 60;
    return c;
}

}  // namespace lucerna
