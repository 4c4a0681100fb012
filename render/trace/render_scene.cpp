#include "render/trace/render_scene.h"

#include "core/scene/room_geometry.h"

#include <algorithm>

namespace lucerna {

namespace {

// Which side of each pane is outside: the side from which rays leave the scene (other panes do
// not stop them) at least three of nine times and more than twice as often as from the other
// (a ray from inside may leave by a door), tried along the normal and eight directions 60
// degrees off it; neither (a pane between two rooms, or standing free) stays unknown.
void markOutsides(const EmbreeScene& accel, std::vector<Portal>& portals, float sceneRadius) {
    const float offset = 1e-4f * sceneRadius;
    const auto escapes = [&](const V3f& centre, const V3f& n) {
        const Frame frame(n);
        int count = 0;
        for (int k = 0; k < 9; ++k) {
            const float phi = float(k) * kPi / 4, sinTheta = k == 8 ? 0.0f : 0.866f, cosTheta = k == 8 ? 1.0f : 0.5f;
            const V3f d = n * cosTheta + (frame.s * std::cos(phi) + frame.t * std::sin(phi)) * sinTheta;
            count += accel.occluded(Ray{centre + n * offset, d}) ? 0 : 1;
        }
        return count;
    };
    for (Portal& p : portals) {
        const V3f centre = (p.p0 + p.p1 + p.p2) / 3.0f;
        const int front = escapes(centre, p.normal), back = escapes(centre, -p.normal);
        p.outside = front >= 3 && front > 2 * back ? int8_t(1) : back >= 3 && back > 2 * front ? int8_t(-1) : int8_t(0);
    }
}

}  // namespace

RenderScene::RenderScene(SceneSnapshot scene, int width, int height, const Sensor* sensor,
                         LightSelection lightSelection, bool daylightPortals)
    : scene_(std::move(scene)), features_(analyseFeatures(*scene_)) {
    const Scene& s = *scene_;
    camera_ = sensor ? *sensor
                     : Sensor(PinholeCamera(s.camera, width > 0 ? width : s.camera.width,
                                            height > 0 ? height : s.camera.height));
    metersPerUnit_ = float(s.metersPerUnit);
    for (const Material& m : s.materials) materials_.push_back(ShadingMaterial::fromMaterial(m));

    std::vector<EmitterTriangle> emitters;
    std::vector<Portal> portals;
    PaneTable panes;
    V3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    // Objects marked as openings (Object::portal) are panes that let everything through: the
    // pane machinery then lets rays cross them and sends daylight through them.
    const auto opening = uint32_t(materials_.size());
    if (std::any_of(s.objects.begin(), s.objects.end(), [](const Object& o) { return o.portal; })) {
        ShadingMaterial open;
        open.type = MaterialType::Glazing;
        materials_.push_back(open);
    }
    for (const Object& o : s.objects) {
        if (!o.worldMesh) continue;
        const uint32_t materialId = o.portal ? opening : uint32_t(s.materialIndex(o.material));
        const ShadingMaterial& mat = materials_[materialId];
        const bool emits = mat.isEmitter() && !isBlack(mat.radiance);
        int32_t pane = -1;
        if (mat.type == MaterialType::Glazing) {
            pane = int32_t(panes.transmittance.size());
            panes.transmittance.push_back(mat.transmittance);
        }
        const int base = int(positions_.size());
        for (const V3d& v : o.worldMesh->vertices) {
            positions_.push_back(toFloat(v));
            lo = V3d(std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z));
            hi = V3d(std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z));
        }
        for (const V3i& t : o.worldMesh->triangles) {
            const V3d& a = o.worldMesh->vertices[t.x];
            const V3d cross = (o.worldMesh->vertices[t.y] - a).cross(o.worldMesh->vertices[t.z] - a);
            const double len = cross.length();
            const auto index = uint32_t(triangles_.size());
            triangles_.push_back(V3i(t.x + base, t.y + base, t.z + base));
            triangleMaterial_.push_back(materialId);
            panes.paneOfTriangle.push_back(pane);
            triangleNormal_.push_back(len > 0 ? toFloat(cross / len) : V3f(0, 0, 1));
            triangleArea_.push_back(float(0.5 * len));
            if (pane >= 0 && len > 0) {
                const V3i& g = triangles_.back();
                portals.push_back({positions_[g.x], positions_[g.y], positions_[g.z], triangleNormal_.back(), float(0.5 * len)});
            }
            if (emits && len > 0) {
                const V3i& g = triangles_.back();
                emitters.push_back({index, positions_[g.x], positions_[g.y], positions_[g.z], triangleNormal_.back(),
                                    float(0.5 * len), mat.radiance});
            }
        }
    }
    if (!positions_.empty()) {
        boundsCenter_ = toFloat((lo + hi) * 0.5);
        boundsRadius_ = std::max(float(0.5 * (hi - lo).length()), 1e-30f);
    }

    std::vector<DeltaLight> deltas;
    GoniometricSamplers samplers;
    for (const Light& l : s.lights) {
        DeltaLight d = compileDeltaLight(l, &samplers);
        if (!isBlack(d.intensity)) deltas.push_back(d);
    }
    // Daylight (SPEC.md section 5): a sun without a disc is a directional light after the others;
    // the sky and a sun with a disc are the environment.
    const Daylight daylight = resolveDaylight(s);
    if (daylight.sun && !(daylight.sun->halfAngleRad > 0) && daylight.sun->aboveHorizon) {
        DeltaLight sun;
        sun.type = LightType::Directional;
        sun.direction = toFloat(-daylight.sun->towardSun);
        sun.intensity = toFloat(daylight.sun->irradiance());
        if (!isBlack(sun.intensity)) {
            directionalSun_ = uint32_t(emitters.size() + deltas.size());
            deltas.push_back(sun);
        }
    }
    // A drawn room's doors and plain openings are portals too, though no pane fills them.
    for (const Room& room : s.rooms)
        for (const std::array<V3d, 4>& c : unglazedOpenings(room, s.materials))
            for (const auto& [a, b, d] : {std::array<V3d, 3>{c[0], c[1], c[2]}, std::array<V3d, 3>{c[0], c[2], c[3]}}) {
                const V3d cross = (b - a).cross(d - a);
                if (cross.length() > 0)
                    portals.push_back({toFloat(a), toFloat(b), toFloat(d), toFloat(cross.normalized()), float(0.5 * cross.length())});
            }
    if (panes.empty()) panes.paneOfTriangle.clear();
    accel_ = std::make_unique<EmbreeScene>(positions_, triangles_, std::move(panes));
    std::optional<EnvironmentLight> environment = EnvironmentLight::fromDaylight(daylight);
    if (environment && portals.size() <= kMaxPortalTriangles) markOutsides(*accel_, portals, boundsRadius_);
    lights_ = LightSampler(std::move(emitters), std::move(deltas), metersPerUnit_, boundsCenter_, boundsRadius_,
                           triangles_.size(), lightSelection, std::move(environment), std::move(portals), daylightPortals);
}

SurfacePoint RenderScene::surfacePoint(uint32_t tri, float b1, float b2) const {
    const V3i& t = triangles_[tri];
    const V3f &p0 = positions_[t.x], &p1 = positions_[t.y], &p2 = positions_[t.z];
    const float b0 = 1.0f - b1 - b2;
    SurfacePoint sp;
    sp.p = p0 * b0 + p1 * b1 + p2 * b2;
    sp.pError = interpolationError(p0, p1, p2, b0, b1, b2);
    sp.ng = triangleNormal_[tri];
    sp.triangle = tri;
    sp.material = triangleMaterial_[tri];
    return sp;
}

std::optional<SurfacePoint> RenderScene::intersect(const Ray& ray, float* t, Rgb* transmittance) const {
    const RayHit hit = accel_->intersect(ray, transmittance);
    if (!hit.found()) return std::nullopt;
    if (t) *t = hit.t;
    return surfacePoint(hit.triangle, hit.b1, hit.b2);
}

void RenderScene::intersectCoherent(std::span<const Ray> rays, std::span<std::optional<SurfacePoint>> hits) const {
    // A packet's width at a time, so that the lens steps' bundles need no heap buffer.
    for (size_t base = 0; base < rays.size(); base += 8) {
        const size_t n = std::min<size_t>(8, rays.size() - base);
        RayHit raw[8];
        accel_->intersectCoherent(rays.data() + base, raw, n);
        for (size_t i = 0; i < n; ++i)
            hits[base + i] = raw[i].found() ? std::optional(surfacePoint(raw[i].triangle, raw[i].b1, raw[i].b2)) : std::nullopt;
    }
}

Rgb RenderScene::transmittanceBetween(const SurfacePoint& a, const SurfacePoint& b) const {
    const V3f d = b.p - a.p;
    const V3f from = a.spawnOrigin(d);
    const V3f to = b.spawnOrigin(-d);
    return accel_->transmittance(Ray{from, to - from, 0.0f, kShadowRayEnd});
}

}  // namespace lucerna
