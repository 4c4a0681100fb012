#include "render/backend/light_layers/light_groups.h"

#include "core/luminaire.h"
#include "core/scene_change.h"

namespace lucerna {

namespace {

bool emits(const Scene& scene, const Object& o) {
    const Material* m = scene.findMaterial(o.material);
    return m && m->type == MaterialType::Emitter && (m->radiance.x > 0 || m->radiance.y > 0 || m->radiance.z > 0);
}

// What a group emits, per channel, in the units its layer scales with.
Rgbd emission(const Scene& scene, const LightGroup& g) {
    if (g.isObject) {
        const Material* m = scene.findMaterial(scene.objects[size_t(g.index)].material);
        return m ? m->radiance : Rgbd(0, 0, 0);
    }
    const Light& l = scene.lights[size_t(g.index)];
    switch (l.type) {
    case LightType::Directional: return l.irradiance;
    case LightType::Luminaire: return luminaireRadiantScale(l);
    default: return l.intensity;
    }
}

}  // namespace

std::vector<LightGroup> lightGroups(const Scene& scene) {
    std::vector<LightGroup> groups;
    for (size_t i = 0; i < scene.lights.size(); ++i) groups.push_back({scene.lights[i].name, false, int(i)});
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (emits(scene, scene.objects[i])) groups.push_back({scene.objects[i].name, true, int(i)});
    return groups;
}

Scene sceneLitBy(const Scene& scene, const LightGroup& group) {
    Scene lit = scene;
    lit.lights.clear();
    if (!group.isObject) lit.lights.push_back(scene.lights[size_t(group.index)]);
    // Other emitters keep their geometry under a black emitter material of their own.
    std::string off = "light layer: off";
    while (lit.findMaterial(off)) off += "'";
    Material black;
    black.name = off;
    black.type = MaterialType::Emitter;
    lit.materials.push_back(black);
    for (size_t i = 0; i < lit.objects.size(); ++i)
        if (!(group.isObject && int(i) == group.index) && emits(scene, scene.objects[i])) lit.objects[i].material = off;
    return lit;
}

std::string lightLayerChannel(const LightGroup& group, char c) {
    return (group.isObject ? "emitter." : "light.") + group.name + "." + c;
}

std::optional<std::vector<Rgb>> layerWeights(const Scene& rendered, const Scene& current) {
    const std::vector<LightGroup> groups = lightGroups(rendered);
    if (!diff(rendered, current).emissionOnly) return std::nullopt;
    // An emitter that was black is not a group of the render: it must stay black.
    for (const Object& o : current.objects)
        if (emits(current, o) && !emits(rendered, o)) return std::nullopt;

    std::vector<Rgb> weights;
    for (const LightGroup& g : groups) {
        const Rgbd before = emission(rendered, g), after = emission(current, g);
        Rgb w;
        for (int c = 0; c < 3; ++c) {
            if (before[c] > 0) w[c] = float(after[c] / before[c]);
            else if (after[c] == 0) w[c] = 0.0f;
            else return std::nullopt;  // a channel that was dark holds nothing to scale
        }
        weights.push_back(w);
    }
    return weights;
}

void mixLightLayers(Image& image, const std::vector<LightGroup>& groups, const std::vector<Rgb>& weights) {
    std::fill(image.pixels.begin(), image.pixels.end(), Rgb(0, 0, 0));
    for (size_t g = 0; g < groups.size() && g < weights.size(); ++g)
        for (int c = 0; c < 3; ++c) {
            const auto it = image.channels.find(lightLayerChannel(groups[g], "RGB"[c]));
            if (it == image.channels.end()) continue;
            const float w = weights[g][c];
            for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i][c] += w * it->second[i];
        }
}

}  // namespace lucerna
