#include "core/scene/room_geometry.h"

#include "core/number_format.h"
#include "core/scene/scene_geometry.h"
#include "core/scene/scene_resolve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace lucerna {

namespace {

std::string unique(std::set<std::string>& taken, const std::string& base) {
    std::string name = base;
    for (int i = 2; taken.count(name); ++i) name = base + " " + std::to_string(i);
    taken.insert(name);
    return name;
}

std::string num(double x) { return shortestNumber(x); }
std::string openingKey(size_t i) { return "openings[" + std::to_string(i) + "]"; }

V3d onFloor(const V2d& p, double y) { return V3d(p.x, y, p.y); }

MeshSource quad(std::array<V3d, 4> corners, const V3d& facing) {
    const V3d normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    if (normal.dot(facing) < 0) std::swap(corners[1], corners[3]);
    MeshSource mesh;
    mesh.kind = MeshSource::Kind::Quad;
    mesh.quad = corners;
    return mesh;
}

bool convex(const PlanPolygon& p) {
    int sign = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const V2d a = p[(i + 1) % p.size()] - p[i], b = p[(i + 2) % p.size()] - p[(i + 1) % p.size()];
        const double c = a.x * b.y - a.y * b.x;
        if (c == 0) return false;
        if (sign == 0) sign = c > 0 ? 1 : -1;
        else if ((c > 0 ? 1 : -1) != sign) return false;
    }
    return true;
}

// The outline as a horizontal surface at height y facing `facing` (up for the floor, down for the
// ceiling): a quad for a convex four-cornered outline, else its triangulation.
MeshSource horizontal(const PlanPolygon& outline, double y, const V3d& facing) {
    if (outline.size() == 4 && convex(outline))
        return quad({onFloor(outline[0], y), onFloor(outline[1], y), onFloor(outline[2], y), onFloor(outline[3], y)}, facing);
    MeshSource mesh;
    mesh.kind = MeshSource::Kind::Inline;
    for (const V2d& p : outline) mesh.inlineMesh.vertices.push_back(onFloor(p, y));
    for (auto t : triangulate(outline)) {
        const auto& v = mesh.inlineMesh.vertices;
        if ((v[size_t(t[1])] - v[size_t(t[0])]).cross(v[size_t(t[2])] - v[size_t(t[0])]).dot(facing) < 0)
            std::swap(t[1], t[2]);
        mesh.inlineMesh.triangles.emplace_back(t[0], t[1], t[2]);
    }
    return mesh;
}

// A point of a wall: `along` from its first corner, `up` above the floor.
V3d onWall(const RoomWall& w, double floorY, double along, double up) {
    // The corners exactly, so that walls, floor and ceiling meet edge to edge.
    const V2d p = along <= 0 ? w.from : along >= w.length ? w.to : w.from + (w.to - w.from) * (along / w.length);
    return V3d(p.x, floorY + up, p.y);
}

struct Rect {
    double s0, s1, t0, t1;  // along the wall, above the floor
};

Rect openingRect(const RoomOpening& o) { return {o.offset, o.offset + o.width, o.sill, o.sill + o.height}; }

// A wall of `height` with holes: the rectangle cut by the holes' edges into a grid, every cell
// outside the holes two triangles. Cells share whole edges, so the wall has no T-junctions.
MeshSource wallWithHoles(const RoomWall& w, double floorY, double height, const std::vector<Rect>& holes, const V3d& facing) {
    std::vector<double> s{0, w.length}, t{0, height};
    for (const Rect& h : holes) {
        s.insert(s.end(), {h.s0, h.s1});
        t.insert(t.end(), {h.t0, h.t1});
    }
    for (auto* axis : {&s, &t}) {
        std::sort(axis->begin(), axis->end());
        axis->erase(std::unique(axis->begin(), axis->end()), axis->end());
    }
    MeshSource mesh;
    mesh.kind = MeshSource::Kind::Inline;
    TriangleMesh& m = mesh.inlineMesh;
    std::vector<int> index(s.size() * t.size(), -1);
    const auto vertex = [&](size_t i, size_t j) {
        int& k = index[j * s.size() + i];
        if (k < 0) {
            k = int(m.vertices.size());
            m.vertices.push_back(onWall(w, floorY, s[i], t[j]));
        }
        return k;
    };
    for (size_t j = 0; j + 1 < t.size(); ++j)
        for (size_t i = 0; i + 1 < s.size(); ++i) {
            const double sm = 0.5 * (s[i] + s[i + 1]), tm = 0.5 * (t[j] + t[j + 1]);
            const bool hole = std::any_of(holes.begin(), holes.end(),
                                          [&](const Rect& h) { return h.s0 < sm && sm < h.s1 && h.t0 < tm && tm < h.t1; });
            if (hole) continue;
            const int a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
            V3i t1(a, b, c), t2(a, c, d);
            const V3d n = (m.vertices[size_t(b)] - m.vertices[size_t(a)]).cross(m.vertices[size_t(c)] - m.vertices[size_t(a)]);
            if (n.dot(facing) < 0) t1 = V3i(a, c, b), t2 = V3i(a, d, c);
            m.triangles.push_back(t1);
            m.triangles.push_back(t2);
        }
    return mesh;
}

}  // namespace

const char* openingTypeName(OpeningType type) {
    switch (type) {
    case OpeningType::Window: return "window";
    case OpeningType::Door: return "door";
    case OpeningType::Opening: return "opening";
    }
    return "opening";
}

std::vector<RoomWall> roomWalls(const Room& room) {
    std::vector<RoomWall> walls;
    const PlanPolygon& p = room.outline;
    const double sign = signedArea(p) >= 0 ? 1 : -1;  // counter-clockwise: the room lies to the left
    for (size_t i = 0; i < p.size(); ++i) {
        RoomWall w;
        w.from = p[i];
        w.to = p[(i + 1) % p.size()];
        w.length = (w.to - w.from).length();
        const V2d d = w.length > 0 ? (w.to - w.from) / w.length : V2d(0, 0);
        w.inward = V2d(-d.y, d.x) * sign;
        walls.push_back(w);
    }
    return walls;
}

std::optional<RoomProblem> roomProblem(const Room& room, const std::vector<Material>& materials) {
    if (room.name.empty()) return RoomProblem{"name", "a room's name is empty"};
    if (room.name.find('\0') != std::string::npos) return RoomProblem{"name", "a room's name contains a NUL character"};
    if (!room.parametric()) return std::nullopt;
    if (auto p = outlineProblem(room.outline)) return RoomProblem{"outline", *p};
    if (!(room.height > 0) || !std::isfinite(room.height))
        return RoomProblem{"height", "a room's height must be positive, got " + num(room.height)};
    if (!std::isfinite(room.floorLevel)) return RoomProblem{"floor_level", "must be a finite number"};
    const auto findMaterial = [&](const std::string& name) -> const Material* {
        for (const Material& m : materials)
            if (m.name == name) return &m;
        return nullptr;
    };
    const std::pair<const char*, const std::string*> surfaces[] = {
        {"materials.floor", &room.floorMaterial}, {"materials.walls", &room.wallMaterial}, {"materials.ceiling", &room.ceilingMaterial}};
    for (const auto& [key, name] : surfaces)
        if (!findMaterial(*name)) return RoomProblem{key, "unknown material " + quote(*name)};

    const std::vector<RoomWall> walls = roomWalls(room);
    for (size_t i = 0; i < room.openings.size(); ++i) {
        const RoomOpening& o = room.openings[i];
        const std::string key = openingKey(i), what = openingTypeName(o.type);
        if (o.wall < 1 || size_t(o.wall) > walls.size())
            return RoomProblem{key + ".wall", "the room has walls 1 to " + std::to_string(walls.size()) + ", got " + std::to_string(o.wall)};
        for (const auto& [name, value] : {std::pair{"width", o.width}, std::pair{"height", o.height}})
            if (!(value > 0) || !std::isfinite(value))
                return RoomProblem{key + "." + name, std::string("must be positive, got ") + num(value)};
        for (const auto& [name, value] : {std::pair{"offset", o.offset}, std::pair{"sill", o.sill}})
            if (!(value >= 0) || !std::isfinite(value))
                return RoomProblem{key + "." + name, std::string("must be at least 0, got ") + num(value)};
        if (o.type == OpeningType::Door && o.sill != 0) return RoomProblem{key + ".sill", "a door reaches the floor: its sill is 0"};
        const RoomWall& w = walls[size_t(o.wall - 1)];
        const double slack = 1e-9 * std::max(w.length, room.height);
        if (o.offset + o.width > w.length + slack)
            return RoomProblem{key, "the " + what + " does not fit wall " + std::to_string(o.wall) + ", which is " + num(w.length) +
                                        " long: offset " + num(o.offset) + " + width " + num(o.width) + " = " +
                                        num(o.offset + o.width)};
        if (o.sill + o.height > room.height + slack)
            return RoomProblem{key, "the " + what + " does not fit under the ceiling: sill " + num(o.sill) + " + height " +
                                        num(o.height) + " = " + num(o.sill + o.height) + ", above the room's height " +
                                        num(room.height)};
        if (o.type == OpeningType::Window) {
            const Material* glazing = findMaterial(o.glazing);
            if (!glazing) return RoomProblem{key + ".glazing", "unknown material " + quote(o.glazing)};
            if (glazing->type != MaterialType::Glazing)
                return RoomProblem{key + ".glazing", "material " + quote(o.glazing) + " is not a glazing material"};
        }
        const Rect a = openingRect(o);
        for (size_t j = 0; j < i; ++j) {
            const RoomOpening& e = room.openings[j];
            if (e.wall != o.wall) continue;
            const Rect b = openingRect(e);
            if (a.s0 < b.s1 && b.s0 < a.s1 && a.t0 < b.t1 && b.t0 < a.t1)
                return RoomProblem{key, "the " + what + " overlaps " + openingKey(j) + " on wall " + std::to_string(o.wall)};
        }
    }
    return std::nullopt;
}

std::vector<Object> roomSurfaces(const Room& room, const Scene& scene, std::set<std::string>& taken) {
    if (!room.parametric()) throw std::invalid_argument("room " + quote(room.name) + " has no outline: its surfaces are marked, not made");
    if (auto p = roomProblem(room, scene.materials)) throw std::invalid_argument(p->key + ": " + p->problem);
    const double y0 = room.floorLevel, y1 = room.floorLevel + room.height;
    std::vector<Object> out;
    const auto add = [&](const std::string& what, const std::string& material, MeshSource mesh) {
        Object o;
        o.name = unique(taken, room.name + " " + what);
        o.material = material;
        o.mesh = std::move(mesh);
        o.room = room.name;
        out.push_back(resolvedObject(scene, std::move(o)));
    };
    add("floor", room.floorMaterial, horizontal(room.outline, y0, V3d(0, 1, 0)));
    add("ceiling", room.ceilingMaterial, horizontal(room.outline, y1, V3d(0, -1, 0)));
    const std::vector<RoomWall> walls = roomWalls(room);
    for (size_t k = 0; k < walls.size(); ++k) {
        const RoomWall& w = walls[k];
        const V3d in(w.inward.x, 0, w.inward.y);
        std::vector<Rect> holes;
        for (const RoomOpening& o : room.openings)
            if (size_t(o.wall) == k + 1) holes.push_back(openingRect(o));
        add("wall " + std::to_string(k + 1), room.wallMaterial,
            holes.empty() ? quad({onWall(w, y0, 0, 0), onWall(w, y0, w.length, 0), onWall(w, y0, w.length, room.height),
                                  onWall(w, y0, 0, room.height)},
                                 in)
                          : wallWithHoles(w, y0, room.height, holes, in));
    }
    int windows = 0;
    for (const RoomOpening& o : room.openings) {
        if (o.type != OpeningType::Window) continue;
        const RoomWall& w = walls[size_t(o.wall - 1)];
        const Rect r = openingRect(o);
        add("window " + std::to_string(++windows), o.glazing,
            quad({onWall(w, y0, r.s0, r.t0), onWall(w, y0, r.s1, r.t0), onWall(w, y0, r.s1, r.t1), onWall(w, y0, r.s0, r.t1)},
                 V3d(w.inward.x, 0, w.inward.y)));
    }
    return out;
}

std::vector<std::array<V3d, 4>> unglazedOpenings(const Room& room, const std::vector<Material>& materials) {
    std::vector<std::array<V3d, 4>> out;
    if (!room.parametric() || roomProblem(room, materials)) return out;
    const std::vector<RoomWall> walls = roomWalls(room);
    for (const RoomOpening& o : room.openings) {
        if (o.type == OpeningType::Window) continue;
        const RoomWall& w = walls[size_t(o.wall - 1)];
        const Rect r = openingRect(o);
        const double y0 = room.floorLevel;
        out.push_back({onWall(w, y0, r.s0, r.t0), onWall(w, y0, r.s1, r.t0), onWall(w, y0, r.s1, r.t1), onWall(w, y0, r.s0, r.t1)});
    }
    return out;
}

double roomFloorArea(const Scene& scene, const Room& room) {
    if (room.parametric()) return std::abs(signedArea(room.outline));
    double lo = 1e300, hi = -1e300;
    for (const Object& o : scene.objects)
        if (o.room == room.name && o.worldMesh)
            for (const V3d& v : o.worldMesh->vertices) lo = std::min(lo, v.y), hi = std::max(hi, v.y);
    double area = 0;
    for (const Object& o : scene.objects) {
        if (o.room != room.name || !o.worldMesh) continue;
        const TriangleMesh& m = *o.worldMesh;
        for (const V3i& t : m.triangles) {
            const V3d &a = m.vertices[size_t(t.x)], &b = m.vertices[size_t(t.y)], &c = m.vertices[size_t(t.z)];
            const V3d n = (b - a).cross(c - a);
            const bool flat = std::abs(n.y) > std::sqrt(0.5) * n.length();
            if (flat && std::max({a.y, b.y, c.y}) <= lo + 0.01 * (hi - lo)) area += 0.5 * n.length();
        }
    }
    return area;
}

RoomAreas roomAreas(const Room& room) {
    RoomAreas a;
    if (!room.parametric()) return a;
    a.floor = std::abs(signedArea(room.outline));
    for (const RoomWall& w : roomWalls(room)) a.walls += w.length * room.height;
    for (const RoomOpening& o : room.openings) a.openings += o.width * o.height;
    a.walls -= a.openings;
    return a;
}

}  // namespace lucerna
