#include "core/scene/room_geometry.h"

#include "core/scene/scene_geometry.h"

#include <array>
#include <cmath>
#include <set>
#include <stdexcept>

namespace lucerna {

namespace {

std::string unique(std::set<std::string>& taken, const std::string& base) {
    std::string name = base;
    for (int i = 2; taken.count(name); ++i) name = base + " " + std::to_string(i);
    taken.insert(name);
    return name;
}

// A quad with its front (counter-clockwise, SPEC.md) toward `inward`.
MeshSource quadFacing(std::array<V3d, 4> corners, const V3d& inward) {
    const V3d normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    if (normal.dot(inward) < 0) std::swap(corners[1], corners[3]);
    MeshSource mesh;
    mesh.kind = MeshSource::Kind::Quad;
    mesh.quad = corners;
    return mesh;
}

Material diffuse(const std::string& name, double reflectance) {
    Material m;
    m.name = name;
    m.type = MaterialType::Diffuse;
    m.albedo = Rgbd(reflectance, reflectance, reflectance);
    return m;
}

}  // namespace

RoomParts makeRoom(const RoomSpec& spec, const Scene& scene) {
    for (double d : {spec.width, spec.depth, spec.height})
        if (!(d > 0) || !std::isfinite(d)) throw std::invalid_argument("a room's width, depth and height must be positive");
    for (double r : {spec.floorReflectance, spec.wallReflectance, spec.ceilingReflectance})
        if (!(r >= 0 && r <= 1)) throw std::invalid_argument("a reflectance must lie between 0 and 1");
    std::set<std::string> things, materialNames;
    for (const Object& o : scene.objects) things.insert(o.name);
    for (const Light& l : scene.lights) things.insert(l.name);
    for (const Material& m : scene.materials) materialNames.insert(m.name);

    RoomParts out;
    const std::string base = spec.name.empty() ? std::string("room") : spec.name;
    const std::string floorMaterial = unique(materialNames, base + " floor");
    const std::string wallMaterial = unique(materialNames, base + " walls");
    const std::string ceilingMaterial = unique(materialNames, base + " ceiling");
    out.materials = {diffuse(floorMaterial, spec.floorReflectance), diffuse(wallMaterial, spec.wallReflectance),
                     diffuse(ceilingMaterial, spec.ceilingReflectance)};

    const double unit = 1.0 / scene.metersPerUnit;  // metres to scene units
    const V3d lo = spec.corner, hi = spec.corner + V3d(spec.width, spec.height, spec.depth) * unit;
    const auto corner = [&](bool x, bool y, bool z) { return V3d(x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z); };
    struct Face {
        const char* name;
        const std::string* material;
        std::array<V3d, 4> corners;
        V3d inward;
    };
    const Face faces[] = {
        {"floor", &floorMaterial, {corner(0, 0, 0), corner(0, 0, 1), corner(1, 0, 1), corner(1, 0, 0)}, V3d(0, 1, 0)},
        {"ceiling", &ceilingMaterial, {corner(0, 1, 0), corner(0, 1, 1), corner(1, 1, 1), corner(1, 1, 0)}, V3d(0, -1, 0)},
        {"wall 1", &wallMaterial, {corner(0, 0, 0), corner(0, 1, 0), corner(0, 1, 1), corner(0, 0, 1)}, V3d(1, 0, 0)},
        {"wall 2", &wallMaterial, {corner(1, 0, 0), corner(1, 1, 0), corner(1, 1, 1), corner(1, 0, 1)}, V3d(-1, 0, 0)},
        {"wall 3", &wallMaterial, {corner(0, 0, 0), corner(1, 0, 0), corner(1, 1, 0), corner(0, 1, 0)}, V3d(0, 0, 1)},
        {"wall 4", &wallMaterial, {corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1)}, V3d(0, 0, -1)},
    };
    Scene withMaterials;  // the materials the objects are resolved against
    withMaterials.metersPerUnit = scene.metersPerUnit;
    withMaterials.materials = out.materials;
    for (const Face& f : faces) {
        Object o;
        o.name = unique(things, base + " " + f.name);
        o.material = *f.material;
        o.mesh = quadFacing(f.corners, f.inward);
        out.objects.push_back(resolvedObject(withMaterials, std::move(o)));
    }
    return out;
}

}  // namespace lucerna
