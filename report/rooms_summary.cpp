#include "report/rooms_summary.h"

#include "core/scene/plan_polygon.h"
#include "core/scene/room_edit.h"
#include "core/scene/room_geometry.h"
#include "report/room_summary.h"

#include <algorithm>
#include <limits>

namespace lucerna {

namespace {

struct Box {
    V3d lo, hi;
};

// A drawn room's outline by its floor and ceiling; a marked room's surfaces' bounds (nothing
// when none of its objects has a mesh).
std::optional<Box> roomBox(const Scene& scene, const Room& room) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Box b{V3d(inf, inf, inf), V3d(-inf, -inf, -inf)};
    const auto grow = [&](const V3d& p) {
        b.lo = V3d(std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z));
        b.hi = V3d(std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z));
    };
    if (room.parametric()) {
        for (const V2d& p : room.outline) {
            grow(V3d(p.x, room.floorLevel, p.y));
            grow(V3d(p.x, room.floorLevel + room.height, p.y));
        }
        return b;
    }
    for (const Object& o : scene.objects)
        if (o.room == room.name && o.worldMesh)
            for (const V3d& v : o.worldMesh->vertices) grow(v);
    if (!(b.lo.x <= b.hi.x)) return std::nullopt;
    return b;
}

// Whether a light stands in the room: within its outline in plan (a marked room: its bounds)
// and between its floor and ceiling.
bool inside(const Room& room, const Box& box, const V3d& p) {
    if (p.y < box.lo.y || p.y > box.hi.y) return false;
    if (room.parametric()) return containsPoint(room.outline, V2d(p.x, p.z));
    return p.x >= box.lo.x && p.x <= box.hi.x && p.z >= box.lo.z && p.z <= box.hi.z;
}

MaintenanceRange lightsRange(const Scene& scene, const Room& room, const Box& box, int& count) {
    std::vector<double> factors;
    for (const Light& l : scene.lights)
        if (l.on && l.type != LightType::Sun && l.type != LightType::Directional && inside(room, box, l.position))
            factors.push_back(maintenanceFactor(scene, l));
    count = int(factors.size());
    if (factors.empty()) return maintenanceRange(scene);
    const auto [lo, hi] = std::minmax_element(factors.begin(), factors.end());
    return {*lo, *hi, true};
}

}  // namespace

RoomsSummary roomsSummary(const Scene& scene) {
    RoomsSummary out;
    const double mpu = scene.metersPerUnit, m2 = mpu * mpu;
    for (const Room& room : scene.rooms) {
        RoomEntry e;
        e.name = room.name;
        e.drawn = room.parametric();
        e.floorAreaM2 = roomFloorArea(scene, room) * m2;
        const std::optional<Box> box = roomBox(scene, room);
        if (box) {
            e.widthM = (box->hi.x - box->lo.x) * mpu;
            e.depthM = (box->hi.z - box->lo.z) * mpu;
            e.heightM = (box->hi.y - box->lo.y) * mpu;
            e.maintenance = lightsRange(scene, room, *box, e.lightsInside);
        } else {
            e.maintenance = maintenanceRange(scene);
        }
        if (e.drawn) {
            const RoomAreas areas = roomAreas(room);
            e.wallAreaM2 = areas.walls * m2;
            e.openingAreaM2 = areas.openings * m2;
            e.materials = {room.floorMaterial, room.wallMaterial, room.ceilingMaterial};
            e.reflectances = roomReflectances(room, scene.materials);
            for (const RoomOpening& o : room.openings)
                ++(o.type == OpeningType::Window ? e.windows : o.type == OpeningType::Door ? e.doors : e.plainOpenings);
        } else {
            const auto surfaces = mainSurfaces(scene, [&](const Object& o) { return o.room == room.name; });
            for (size_t k = 0; k < 3; ++k) {
                e.materials[k] = surfaces[k].material;
                if (!surfaces[k].material.empty()) e.reflectances[k] = surfaces[k].reflectance;
            }
        }
        out.rooms.push_back(std::move(e));
    }
    return out;
}

}  // namespace lucerna
