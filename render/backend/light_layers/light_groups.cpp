#include "render/backend/light_layers/light_groups.h"

#include "core/photometry/luminaire.h"
#include "core/scene/scene_change.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace lucerna {

namespace {

bool emits(const Scene& scene, const Object& o) {
    const Material* m = scene.findMaterial(o.material);
    return m && m->type == MaterialType::Emitter && (m->radiance.x > 0 || m->radiance.y > 0 || m->radiance.z > 0);
}

// What a light emits, per channel, in the units its layer scales with (nothing when it is off).
Rgbd lightEmission(const Light& l) {
    if (!l.on) return Rgbd(0, 0, 0);
    switch (l.type) {
    case LightType::Directional: return l.irradiance;
    case LightType::Luminaire: return luminaireRadiantScale(l);
    default: return l.intensity;
    }
}

// The one factor per channel that takes every `before` to its `after`: a layer holding several
// lights scales only when they all scaled alike. Pairs dark before and after add nothing; a
// channel dark before and lit after has nothing to scale.
std::optional<Rgb> commonFactor(const std::vector<std::pair<Rgbd, Rgbd>>& beforeAfter) {
    Rgb w(0, 0, 0);
    for (int c = 0; c < 3; ++c) {
        std::optional<double> factor;
        for (const auto& [before, after] : beforeAfter) {
            if (!(before[c] > 0)) {
                if (after[c] == 0) continue;
                return std::nullopt;
            }
            const double r = after[c] / before[c];
            if (factor && std::abs(r - *factor) > 1e-9 * std::max(std::abs(r), std::abs(*factor))) return std::nullopt;
            if (!factor) factor = r;
        }
        w[c] = float(factor.value_or(0.0));
    }
    return w;
}

}  // namespace

std::vector<LightGroup> lightGroups(const Scene& scene) {
    std::vector<LightGroup> groups;
    std::unordered_map<std::string, size_t> sceneGroup;  // a scene group's name -> its place in `groups`
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        if (!l.on) continue;
        if (l.group.empty()) {
            groups.push_back({l.name, false, int(i), {}});
            continue;
        }
        const auto [it, fresh] = sceneGroup.try_emplace(l.group, groups.size());
        if (fresh) groups.push_back({l.group, false, int(i), {}});
        groups[it->second].members.push_back(int(i));
    }
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (emits(scene, scene.objects[i])) groups.push_back({scene.objects[i].name, true, int(i), {}});
    return groups;
}

std::string lightLayerLimitMessage(size_t layers) {
    return "per-light layers: the scene would need " + std::to_string(layers) +
           " layers (one per light outside a group, per group and per emitting object), more than " +
           std::to_string(kMaxLightLayers) + "; put lights into groups (\"group\") or render without layers";
}

Scene sceneLitBy(const Scene& scene, const LightGroup& group) {
    Scene lit = scene;
    lit.lights.clear();
    if (group.isSceneGroup())
        for (int i : group.members) lit.lights.push_back(scene.lights[size_t(i)]);
    else if (!group.isObject)
        lit.lights.push_back(scene.lights[size_t(group.index)]);
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
    return (group.isObject ? "emitter." : group.isSceneGroup() ? "group." : "light.") + group.name + "." + c;
}

std::optional<std::vector<Rgb>> layerWeights(const Scene& rendered, const Scene& current) {
    if (!diff(rendered, current).emissionOnly) return std::nullopt;
    // An emitter that was black, or a light that was switched off, has no layer: it must stay dark.
    for (const Object& o : current.objects)
        if (emits(current, o) && !emits(rendered, o)) return std::nullopt;
    for (size_t i = 0; i < current.lights.size(); ++i)
        if (current.lights[i].on && !rendered.lights[i].on) return std::nullopt;

    std::vector<Rgb> weights;
    for (const LightGroup& g : lightGroups(rendered)) {
        std::vector<std::pair<Rgbd, Rgbd>> beforeAfter;
        if (g.isObject) {
            const auto radiance = [&g](const Scene& s) {
                const Material* m = s.findMaterial(s.objects[size_t(g.index)].material);
                return m ? m->radiance : Rgbd(0, 0, 0);
            };
            beforeAfter.emplace_back(radiance(rendered), radiance(current));
        } else if (g.isSceneGroup()) {
            for (int i : g.members)
                beforeAfter.emplace_back(lightEmission(rendered.lights[size_t(i)]), lightEmission(current.lights[size_t(i)]));
        } else {
            beforeAfter.emplace_back(lightEmission(rendered.lights[size_t(g.index)]),
                                     lightEmission(current.lights[size_t(g.index)]));
        }
        const std::optional<Rgb> w = commonFactor(beforeAfter);
        if (!w) return std::nullopt;
        weights.push_back(*w);
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
