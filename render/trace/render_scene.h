#pragma once
// A scene compiled for tracing: flat float triangle arrays, per-triangle material and geometric
// normal, shading materials, the camera at the requested resolution, lights and the Embree BVH.
// Built once per snapshot; immutable and shared by all threads of a backend afterwards.

#include "core/scene/scene.h"
#include "render/trace/bsdf.h"
#include "render/trace/embree_scene.h"
#include "render/trace/lights/light_sampler.h"
#include "render/trace/sensor.h"
#include "render/trace/surface_point.h"

#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace lucerna {

class RenderScene {
public:
    // width/height: the film resolution (the camera's own when <= 0). With `sensor`, the film
    // measures that sensor instead of the scene's camera (irradiance sensors; sensor.h).
    // daylightPortals: daylight particles through the windows (daylight_portals.h; off by
    // default: README, "Daylight in the renderers").
    RenderScene(SceneSnapshot scene, int width = 0, int height = 0, const Sensor* sensor = nullptr,
                LightSelection lightSelection = kDefaultLightSelection, bool daylightPortals = false);

    const Scene& scene() const { return *scene_; }
    const SceneSnapshot& snapshot() const { return scene_; }
    const SceneFeatures& features() const { return features_; }
    const Sensor& camera() const { return camera_; }
    const EmbreeScene& accel() const { return *accel_; }
    const LightSampler& lights() const { return lights_; }
    // The sun of diameter 0 above the horizon as a directional light, numbered as
    // LightSample::light (after the scene's own delta lights); nothing without one.
    std::optional<uint32_t> directionalSun() const { return directionalSun_; }
    float metersPerUnit() const { return metersPerUnit_; }

    size_t triangleCount() const { return triangles_.size(); }
    const ShadingMaterial& material(uint32_t id) const { return materials_[id]; }
    // The scene's materials, then one for the objects marked as openings (Object::portal) if any.
    size_t materialCount() const { return materials_.size(); }
    const ShadingMaterial& materialOfTriangle(uint32_t tri) const { return materials_[triangleMaterial_[tri]]; }
    const V3f& normalOfTriangle(uint32_t tri) const { return triangleNormal_[tri]; }
    std::array<V3f, 3> verticesOfTriangle(uint32_t tri) const {
        const V3i& t = triangles_[tri];
        return {positions_[t.x], positions_[t.y], positions_[t.z]};
    }

    // Closest surface along the ray, if any. Glazing is crossed, never hit (SPEC.md section 5):
    // with `transmittance`, what the panes before the hit (or along the whole ray on a miss)
    // let through, per unit.
    std::optional<SurfacePoint> intersect(const Ray& ray, float* t = nullptr, Rgb* transmittance = nullptr) const;
    // Closest hits of a bundle of coherent rays (camera rays through nearby pixels), traced as
    // Embree packets: the same answers as intersect(), ray by ray.
    void intersectCoherent(std::span<const Ray> rays, std::span<std::optional<SurfacePoint>> hits) const;
    // Point at barycentrics (b1, b2) of a triangle, with its error bound.
    SurfacePoint surfacePoint(uint32_t tri, float b1, float b2) const;
    // What passes along the segment between two surface points (each offset off its surface
    // toward the other), per unit: 0 when an opaque surface blocks it, else the product of the
    // transmittances of the panes it crosses (1 without glazing).
    Rgb transmittanceBetween(const SurfacePoint& a, const SurfacePoint& b) const;
    // The same along a shadow ray (LightSample::shadowRay).
    Rgb transmittance(const Ray& ray) const { return accel_->transmittance(ray); }
    // True when any surface blocks the ray, panes included (transmittance() crosses them).
    bool occluded(const Ray& ray) const { return accel_->occluded(ray); }
    bool hasGlazing() const { return accel_->hasPanes(); }
    // Radiance (W sr^-1 m^-2) arriving from infinity along -w for a ray leaving the scene in unit
    // direction w: the sky, the ground below the horizon and the sun's disc; 0 without daylight.
    Rgb escapedRadiance(const V3f& w) const { return lights_.environment() ? lights_.environment()->radiance(w) : Rgb(0, 0, 0); }
    // Benchmarks only: records every ray traced from now on (nullptr stops).
    void setRayRecorder(RayRecorder* recorder) { accel_->setRecorder(recorder); }

    // Centre and radius of a sphere bounding the geometry (directional lights use it).
    const V3f& boundsCenter() const { return boundsCenter_; }
    float boundsRadius() const { return boundsRadius_; }

private:
    SceneSnapshot scene_;
    SceneFeatures features_;
    Sensor camera_;
    float metersPerUnit_ = 1.0f;
    std::vector<ShadingMaterial> materials_;
    std::vector<V3f> positions_;
    std::vector<V3i> triangles_;
    std::vector<uint32_t> triangleMaterial_;
    std::vector<V3f> triangleNormal_;
    std::vector<float> triangleArea_;
    V3f boundsCenter_{0, 0, 0};
    float boundsRadius_ = 1.0f;
    std::unique_ptr<EmbreeScene> accel_;
    LightSampler lights_;
    std::optional<uint32_t> directionalSun_;
};

}  // namespace lucerna
