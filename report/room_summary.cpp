#include "report/room_summary.h"

#include "core/photometry/photometric_units.h"
#include "core/scene/scene_geometry.h"
#include "report/report_data.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace lucerna {

namespace {

enum Facing { Up = 0, Sideways = 1, Down = 2 };

Facing facingOf(const V3d& normal) {
    constexpr double kCos45 = 0.70710678118654752;
    if (normal.y >= kCos45) return Up;
    if (normal.y <= -kCos45) return Down;
    return Sideways;
}

bool hasDiffusePart(const Material& m) { return m.type == MaterialType::Diffuse || m.type == MaterialType::Glossy; }

}  // namespace

std::array<MainSurface, 3> mainSurfaces(const Scene& scene, const std::function<bool(const Object&)>& include) {
    const double mpu = scene.metersPerUnit, m2 = mpu * mpu;
    // Area per material per facing, m².
    std::array<std::map<std::string, double>, 3> areas;
    for (const Object& o : scene.objects) {
        const Material* m = scene.findMaterial(o.material);
        if (!m || !hasDiffusePart(*m) || !o.worldMesh || !include(o)) continue;
        const TriangleMesh& mesh = *o.worldMesh;
        for (const V3i& t : mesh.triangles) {
            const V3d& a = mesh.vertices[size_t(t.x)];
            const V3d n = (mesh.vertices[size_t(t.y)] - a).cross(mesh.vertices[size_t(t.z)] - a);
            const double twice = n.length();
            if (!(twice > 0)) continue;
            areas[facingOf(n / twice)][m->name] += 0.5 * twice * m2;
        }
    }
    std::array<MainSurface, 3> surfaces;
    const char* roles[3] = {"Floor", "Walls", "Ceiling"};
    for (int f = 0; f < 3; ++f) {
        MainSurface& s = surfaces[size_t(f)];
        s.role = roles[f];
        for (const auto& [name, area] : areas[size_t(f)]) {
            s.facingAreaM2 += area;
            if (area > s.areaM2) s.areaM2 = area, s.material = name;
        }
        if (const Material* m = scene.findMaterial(s.material)) s.reflectance = luminance(m->albedo);
    }
    return surfaces;
}

RoomSummary roomSummary(const Scene& scene, const Schedule& schedule) {
    RoomSummary r;
    const double mpu = scene.metersPerUnit;
    const SceneBounds b = sceneBounds(scene);
    r.widthM = (b.hi.x - b.lo.x) * mpu;
    r.depthM = (b.hi.z - b.lo.z) * mpu;
    r.heightM = (b.hi.y - b.lo.y) * mpu;
    r.surfaces = mainSurfaces(scene, [](const Object&) { return true; });

    r.maintenance = maintenanceRange(scene);
    r.sceneMaintenance = scene.maintenance;
    r.luminaires = schedule.luminaires;
    r.connectedLoadW = schedule.totalWatts;
    r.withoutWatts = schedule.withoutWatts;
    r.floorAreaM2 = schedule.floorAreaM2;
    return r;
}

}  // namespace lucerna
