#include "core/scene/scene_change.h"

namespace lucerna {

namespace {

// A sun whose direction comes from the site's clock (SPEC.md section 5).
bool placedByTime(const Light& l) { return l.type == LightType::Sun && l.sun && l.sun->time; }

bool sameMaterials(const Scene& a, const Scene& b) {
    if (a.materials != b.materials || a.metersPerUnit != b.metersPerUnit) return false;
    for (size_t i = 0; i < a.objects.size() && i < b.objects.size(); ++i)
        if (a.objects[i].material != b.objects[i].material) return false;
    return true;
}

// `after` with `before`'s emission put back equals `before` (compared part by part, so that no
// copy of the scene is made).
bool differOnlyInEmission(const Scene& before, const Scene& after) {
    if (before.version != after.version || before.metersPerUnit != after.metersPerUnit ||
        !(before.camera == after.camera) || before.objects != after.objects ||
        before.lights.size() != after.lights.size() || before.materials.size() != after.materials.size() ||
        before.site != after.site || before.sky != after.sky)
        return false;
    for (size_t i = 0; i < after.lights.size(); ++i) {
        Light l = after.lights[i];
        const Light& r = before.lights[i];
        l.intensity = r.intensity;
        l.irradiance = r.irradiance;
        l.photometric = r.photometric;
        // Switching a light is a change of its emission (to or from none); its group changes
        // nothing that renders. Not so a sun under a sky: the ground's luminance is the sky's
        // and the sun's light together (SPEC.md section 5), so it changes with the sun.
        if (!(l.type == LightType::Sun && after.sky)) l.on = r.on;
        l.group = r.group;
        if (l.luminaire && r.luminaire) {
            l.luminaire->lumens = r.luminaire->lumens;
            l.luminaire->colour = r.luminaire->colour;
            l.luminaire->temperatureK = r.luminaire->temperatureK;
        }
        if (!(l == r)) return false;
    }
    for (size_t i = 0; i < after.materials.size(); ++i) {
        Material m = after.materials[i];
        const Material& r = before.materials[i];
        if (m.type == MaterialType::Emitter && r.type == MaterialType::Emitter) m.radiance = r.radiance;
        if (!(m == r)) return false;
    }
    return true;
}

}  // namespace

bool sameWorldMeshes(const Scene& a, const Scene& b) {
    if (a.objects.size() != b.objects.size()) return false;
    for (size_t i = 0; i < a.objects.size(); ++i)
        if (a.objects[i].worldMesh != b.objects[i].worldMesh) return false;
    return true;
}

SceneChange diff(const Scene& before, const Scene& after) {
    SceneChange c;
    c.geometry = !sameWorldMeshes(before, after);
    c.materials = !sameMaterials(before, after);
    c.resolution = before.camera.width != after.camera.width || before.camera.height != after.camera.height;
    Camera pose = after.camera;
    pose.width = before.camera.width;
    pose.height = before.camera.height;
    c.camera = !(pose == before.camera);
    c.lightSet = before.lights.size() != after.lights.size();
    if (!c.lightSet)
        for (size_t i = 0; i < after.lights.size(); ++i)
            if (!(before.lights[i] == after.lights[i]) || (placedByTime(after.lights[i]) && before.site != after.site))
                c.lights.push_back(i);
    c.daylight = before.site != after.site || before.sky != after.sky;
    c.emissionOnly = differOnlyInEmission(before, after);
    return c;
}

}  // namespace lucerna
