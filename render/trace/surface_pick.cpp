#include "render/trace/surface_pick.h"

#include "core/scene/scene_change.h"
#include "render/trace/embree_scene.h"

#include <limits>

namespace lucerna {

V3d cameraRayDirection(const Camera& c, double x, double y) {
    const V3d f = (c.target - c.position).normalized();
    const V3d r = f.cross(c.up).normalized();
    const V3d u = r.cross(f);
    const double t = std::tan(radians(c.fovYDeg) / 2);
    const double aspect = double(c.width) / double(c.height);
    return (f + r * ((2 * x / c.width - 1) * aspect * t) + u * ((1 - 2 * y / c.height) * t)).normalized();
}

SurfacePicker::SurfacePicker(const Scene& scene) : scene_(scene) {
    std::vector<V3f> positions;
    std::vector<V3i> triangles;
    V3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const auto& mesh = scene.objects[i].worldMesh;
        if (!mesh) continue;
        const int base = int(positions.size());
        for (const V3d& v : mesh->vertices) {
            positions.push_back(toFloat(v));
            lo = V3d(std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z));
            hi = V3d(std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z));
        }
        for (size_t t = 0; t < mesh->triangles.size(); ++t) {
            const V3i& tri = mesh->triangles[t];
            triangles.push_back(V3i(tri.x + base, tri.y + base, tri.z + base));
            owner_.emplace_back(int(i), int(t));
        }
    }
    if (!positions.empty()) diagonal_ = (hi - lo).length();
    accel_ = std::make_unique<EmbreeScene>(positions, triangles);
}

SurfacePicker::~SurfacePicker() = default;

bool SurfacePicker::sameGeometry(const Scene& scene) const {
    return sameWorldMeshes(scene_, scene);
}

std::optional<SurfaceHit> SurfacePicker::intersect(const V3d& origin, const V3d& direction) const {
    const V3d d = direction.normalized();
    const RayHit hit = accel_->intersect(Ray{toFloat(origin), toFloat(d)});
    if (!hit.found()) return std::nullopt;
    const auto [object, triangle] = owner_[hit.triangle];
    const TriangleMesh& mesh = *scene_.objects[size_t(object)].worldMesh;
    const V3i& tri = mesh.triangles[size_t(triangle)];
    const V3d &a = mesh.vertices[size_t(tri.x)], &b = mesh.vertices[size_t(tri.y)], &c = mesh.vertices[size_t(tri.z)];
    SurfaceHit h;
    h.object = object;
    h.triangle = triangle;
    h.normal = (b - a).cross(c - a).normalized();
    // Embree found the triangle in float; the point comes again from the double ray and the
    // triangle's plane, so that it lies on the surface to double precision.
    const double dn = d.dot(h.normal);
    h.distance = std::abs(dn) > 1e-12 ? (a - origin).dot(h.normal) / dn : double(hit.t);
    h.point = origin + d * h.distance;
    if (dn > 0) h.normal = -h.normal;
    return h;
}

std::optional<SurfaceHit> SurfacePicker::pick(const Camera& camera, double x, double y) const {
    return intersect(camera.position, cameraRayDirection(camera, x, y));
}

}  // namespace lucerna
