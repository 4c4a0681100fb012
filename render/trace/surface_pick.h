#pragma once
// Which surface lies under a point of the image: the editor's picking (place a light on a
// surface, aim a spot at one, select an object by clicking it). Rays follow SPEC.md's pinhole
// camera exactly (section 1), in double precision, and are traced through the Embree wrapper.
// A picker holds the geometry of one scene; lights and the camera are not part of it, so one
// picker serves every snapshot whose world meshes are the same (sameGeometry()).

#include "core/scene/scene.h"

#include <memory>
#include <optional>
#include <vector>

namespace lucerna {

class EmbreeScene;

struct SurfaceHit {
    V3d point;           // on the triangle's plane (from the double-precision vertices)
    V3d normal;          // unit geometric normal, turned to face the ray's origin
    int object = -1;     // index into Scene::objects
    int triangle = -1;   // index into that object's worldMesh->triangles
    double distance = 0; // from the ray's origin, in scene units
};

// Unit direction of the camera ray through raster point (x, y) (x right, y down, in
// [0, W] x [0, H] of the camera's resolution), by SPEC.md's formula.
V3d cameraRayDirection(const Camera& camera, double x, double y);

class SurfacePicker {
public:
    // Builds an acceleration structure over the scene's world meshes. Throws std::runtime_error
    // when Embree cannot be initialised.
    explicit SurfacePicker(const Scene& scene);
    ~SurfacePicker();
    SurfacePicker(const SurfacePicker&) = delete;
    SurfacePicker& operator=(const SurfacePicker&) = delete;

    // True when `scene` has exactly the world meshes this picker was built over (the same
    // shared mesh data, in the same objects: no geometry change by core/scene/scene_change.h), so that
    // its answers hold for that scene too.
    bool sameGeometry(const Scene& scene) const;

    // The closest surface along the ray (direction need not be unit), if any.
    std::optional<SurfaceHit> intersect(const V3d& origin, const V3d& direction) const;
    // The closest surface seen through raster point (x, y) of the camera.
    std::optional<SurfaceHit> pick(const Camera& camera, double x, double y) const;

    // Length of the diagonal of the geometry's bounding box (0 when there is no geometry).
    double diagonal() const { return diagonal_; }

private:
    Scene scene_;  // the scene it was built over (its world meshes are shared, not copied)
    std::vector<std::pair<int, int>> owner_;                   // per traced triangle: object, triangle
    std::unique_ptr<EmbreeScene> accel_;
    double diagonal_ = 0;
};

}  // namespace lucerna
