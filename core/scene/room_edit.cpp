#include "core/scene/room_edit.h"

#include "core/mesh/mesh_edges.h"
#include "core/scene/scene_resolve.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace lucerna {

namespace {

std::string freeMaterialName(const std::vector<Material>& materials, const std::string& base) {
    const auto used = [&](const std::string& n) {
        return std::any_of(materials.begin(), materials.end(), [&](const Material& m) { return m.name == n; });
    };
    std::string name = base;
    for (int i = 2; used(name); ++i) name = base + " " + std::to_string(i);
    return name;
}

Material* findIn(std::vector<Material>& materials, const std::string& name) {
    for (Material& m : materials)
        if (m.name == name) return &m;
    return nullptr;
}

void checkRoomName(const Scene& scene, int index, const std::string& name) {
    for (size_t i = 0; i < scene.rooms.size(); ++i)
        if (int(i) != index && scene.rooms[i].name == name)
            throw std::invalid_argument("name: another room is already named " + quote(name));
}

// Whether the object lies flat at height y and overlaps the outline in plan.
bool floorUnder(const Object& object, const Room& room) {
    if (!object.worldMesh || object.worldMesh->vertices.empty()) return false;
    PlanPolygon plan;
    double lo = 1e300, hi = -1e300;
    for (const V3d& v : object.worldMesh->vertices) {
        plan.emplace_back(v.x, v.z);
        lo = std::min(lo, v.y), hi = std::max(hi, v.y);
    }
    const double slack = 1e-6 * std::max(1.0, std::abs(room.height));
    if (std::abs(lo - room.floorLevel) > slack || std::abs(hi - room.floorLevel) > slack) return false;
    // A quad's corners run round it; a mesh of more is judged by its triangles' corners.
    if (plan.size() == 4 && !outlineProblem(plan)) return polygonsOverlap(plan, room.outline);
    for (const V3i& t : object.worldMesh->triangles) {
        const PlanPolygon tri{plan[size_t(t.x)], plan[size_t(t.y)], plan[size_t(t.z)]};
        if (!outlineProblem(tri) && polygonsOverlap(tri, room.outline)) return true;
    }
    return false;
}

// Whether any object but those at `gone` (ascending) or in `added` uses the material.
bool materialInUse(const Scene& scene, const std::vector<std::pair<size_t, Object>>& gone,
                   const std::vector<std::pair<size_t, Object>>& added, const std::string& name) {
    size_t g = 0;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (g < gone.size() && gone[g].first == i) {
            ++g;
            continue;
        }
        if (scene.objects[i].material == name) return true;
    }
    return std::any_of(added.begin(), added.end(), [&](const auto& o) { return o.second.material == name; });
}

}  // namespace

void applyRoomEdit(Scene& scene, const RoomEdit& edit) {
    for (auto it = edit.removed.rbegin(); it != edit.removed.rend(); ++it)
        scene.objects.erase(scene.objects.begin() + std::ptrdiff_t(it->first));
    for (const auto& [index, object] : edit.inserted) scene.objects.insert(scene.objects.begin() + std::ptrdiff_t(index), object);
    scene.rooms = edit.roomsAfter;
    scene.materials = edit.materialsAfter;
}

void revertRoomEdit(Scene& scene, const RoomEdit& edit) {
    for (auto it = edit.inserted.rbegin(); it != edit.inserted.rend(); ++it)
        scene.objects.erase(scene.objects.begin() + std::ptrdiff_t(it->first));
    for (const auto& [index, object] : edit.removed) scene.objects.insert(scene.objects.begin() + std::ptrdiff_t(index), object);
    scene.rooms = edit.roomsBefore;
    scene.materials = edit.materialsBefore;
}

std::vector<size_t> roomObjects(const Scene& scene, const std::string& name) {
    std::vector<size_t> out;
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (!name.empty() && scene.objects[i].room == name) out.push_back(i);
    return out;
}

RoomEdit placeRoom(const Scene& scene, int index, const Room& room, std::vector<Material> materials,
                   std::optional<size_t> placeholderFloor) {
    if (index >= int(scene.rooms.size())) throw std::invalid_argument("no room " + std::to_string(index));
    checkRoomName(scene, index, room.name);
    RoomEdit edit;
    edit.roomsBefore = scene.rooms;
    edit.materialsBefore = scene.materials;
    const std::vector<size_t> old = index >= 0 ? roomObjects(scene, scene.rooms[size_t(index)].name) : std::vector<size_t>{};
    std::vector<size_t> gone = old;
    if (placeholderFloor && *placeholderFloor < scene.objects.size() && scene.objects[*placeholderFloor].room.empty() &&
        floorUnder(scene.objects[*placeholderFloor], room)) {
        gone.push_back(*placeholderFloor);
        std::sort(gone.begin(), gone.end());
        edit.removedPlaceholderFloor = true;
    }
    for (size_t i : gone) edit.removed.emplace_back(i, scene.objects[i]);

    std::set<std::string> taken;
    for (size_t i = 0, g = 0; i < scene.objects.size(); ++i) {
        if (g < gone.size() && gone[g] == i) {
            ++g;
            continue;
        }
        taken.insert(scene.objects[i].name);
    }
    for (const Light& l : scene.lights) taken.insert(l.name);
    Scene resolving;  // what the surfaces' meshes are resolved against
    resolving.metersPerUnit = scene.metersPerUnit;
    resolving.baseDir = scene.baseDir;
    resolving.materials = materials;
    std::vector<Object> surfaces = roomSurfaces(room, resolving, taken);

    // In place of the old surfaces, or after every object for a new room.
    const size_t anchor = old.empty() ? scene.objects.size() : old.front();
    const size_t at = anchor - size_t(std::count_if(gone.begin(), gone.end(), [&](size_t i) { return i < anchor; }));
    for (size_t k = 0; k < surfaces.size(); ++k) edit.inserted.emplace_back(at + k, std::move(surfaces[k]));

    if (edit.removedPlaceholderFloor) {
        const std::string& material = scene.objects[*placeholderFloor].material;
        if (!materialInUse(scene, edit.removed, edit.inserted, material))
            materials.erase(std::remove_if(materials.begin(), materials.end(), [&](const Material& m) { return m.name == material; }),
                            materials.end());
    }
    edit.roomsAfter = scene.rooms;
    if (index >= 0) edit.roomsAfter[size_t(index)] = room;
    else edit.roomsAfter.push_back(room);
    edit.materialsAfter = std::move(materials);
    return edit;
}

void setRoomReflectances(Room& room, std::vector<Material>& materials, const RoomReflectances& r) {
    for (double v : {r.floor, r.walls, r.ceiling})
        if (!(v >= 0 && v <= 1)) throw std::invalid_argument("a reflectance must lie between 0 and 1");
    const std::pair<std::string*, double> surfaces[] = {
        {&room.floorMaterial, r.floor}, {&room.wallMaterial, r.walls}, {&room.ceilingMaterial, r.ceiling}};
    const char* const names[] = {" floor", " walls", " ceiling"};
    for (size_t k = 0; k < 3; ++k) {
        auto [name, value] = surfaces[k];
        if (name->empty()) {
            Material m;
            m.name = freeMaterialName(materials, room.name + names[k]);
            m.type = MaterialType::Diffuse;
            m.albedo = Rgbd(value, value, value);
            *name = m.name;
            materials.push_back(std::move(m));
        } else if (Material* m = findIn(materials, *name); m && (m->type == MaterialType::Diffuse || m->type == MaterialType::Glossy)) {
            m->albedo = Rgbd(value, value, value);
        }
    }
}

std::array<std::optional<double>, 3> roomReflectances(const Room& room, const std::vector<Material>& materials) {
    std::array<std::optional<double>, 3> out;
    const std::string* names[] = {&room.floorMaterial, &room.wallMaterial, &room.ceilingMaterial};
    for (size_t k = 0; k < 3; ++k)
        for (const Material& m : materials)
            if (m.name == *names[k] && (m.type == MaterialType::Diffuse || m.type == MaterialType::Glossy))
                out[k] = luminance(m.albedo);
    return out;
}

std::string glazingMaterial(std::vector<Material>& materials, const std::string& roomName, double transmittance) {
    if (!(transmittance >= 0 && transmittance <= 1)) throw std::invalid_argument("a transmittance must lie between 0 and 1");
    const Rgbd tau(transmittance, transmittance, transmittance);
    for (const Material& m : materials)
        if (m.type == MaterialType::Glazing && m.transmittance == tau) return m.name;
    Material m;
    m.name = freeMaterialName(materials, roomName + " glazing");
    m.type = MaterialType::Glazing;
    m.transmittance = tau;
    materials.push_back(m);
    return m.name;
}

RoomEdit markRoom(const Scene& scene, const std::string& name, const std::vector<int>& objects) {
    if (objects.empty()) throw std::invalid_argument("select the objects that make up the room");
    Room room;
    room.name = name;
    if (auto p = roomProblem(room, scene.materials)) throw std::invalid_argument(p->problem);
    checkRoomName(scene, -1, name);
    std::vector<int> sorted = objects;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    TriangleMesh shell;
    for (int i : sorted) {
        if (i < 0 || size_t(i) >= scene.objects.size()) throw std::invalid_argument("no object " + std::to_string(i));
        const Object& o = scene.objects[size_t(i)];
        if (!o.room.empty()) throw std::invalid_argument(o.name + " is a surface of room " + o.room + " already");
        if (!o.worldMesh) continue;
        const int base = int(shell.vertices.size());
        shell.vertices.insert(shell.vertices.end(), o.worldMesh->vertices.begin(), o.worldMesh->vertices.end());
        for (const V3i& t : o.worldMesh->triangles) shell.triangles.emplace_back(t.x + base, t.y + base, t.z + base);
    }
    if (shell.triangles.empty()) throw std::invalid_argument("the selected objects have no faces");
    if (const size_t open = boundaryEdgeCount(shell))
        throw std::invalid_argument("the selected objects do not form a closed shell: " + std::to_string(open) +
                                    (open == 1 ? " edge belongs" : " edges belong") + " to one face only");
    RoomEdit edit;
    edit.roomsBefore = scene.rooms;
    edit.roomsAfter = scene.rooms;
    edit.roomsAfter.push_back(room);
    edit.materialsBefore = edit.materialsAfter = scene.materials;
    for (int i : sorted) {
        edit.removed.emplace_back(size_t(i), scene.objects[size_t(i)]);
        Object tagged = scene.objects[size_t(i)];
        tagged.room = name;
        edit.inserted.emplace_back(size_t(i), std::move(tagged));
    }
    return edit;
}

RoomEdit removeRoom(const Scene& scene, int index) {
    if (index < 0 || size_t(index) >= scene.rooms.size()) throw std::invalid_argument("no room " + std::to_string(index));
    const Room& room = scene.rooms[size_t(index)];
    RoomEdit edit;
    edit.roomsBefore = scene.rooms;
    edit.roomsAfter = scene.rooms;
    edit.roomsAfter.erase(edit.roomsAfter.begin() + index);
    edit.materialsBefore = edit.materialsAfter = scene.materials;
    for (size_t i : roomObjects(scene, room.name)) {
        edit.removed.emplace_back(i, scene.objects[i]);
        if (!room.parametric()) {
            Object untagged = scene.objects[i];
            untagged.room.clear();
            edit.inserted.emplace_back(i, std::move(untagged));
        }
    }
    if (room.parametric()) {
        std::set<std::string> own{room.floorMaterial, room.wallMaterial, room.ceilingMaterial};
        for (const RoomOpening& o : room.openings)
            if (o.type == OpeningType::Window) own.insert(o.glazing);
        std::erase_if(edit.materialsAfter, [&](const Material& m) {
            return own.count(m.name) && !materialInUse(scene, edit.removed, edit.inserted, m.name);
        });
    }
    return edit;
}

}  // namespace lucerna
