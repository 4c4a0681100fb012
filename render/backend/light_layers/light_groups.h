#pragma once
// Light groups for per-light layers (issue 7): the converged image is linear in the emission of
// each light, so a render kept as one layer per light can be dimmed, switched and recoloured
// afterwards by weighting the layers, with no new render. A group is one light of the scene
// (point, spot, directional, luminaire) or one emissive object.

#include "core/image.h"
#include "core/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct LightGroup {
    std::string name;       // the light's or object's name in the scene
    bool isObject = false;  // an emissive object (else Scene::lights[index])
    int index = 0;          // into Scene::lights or Scene::objects
};

// Every light of the scene in file order, then every object whose material emits (non-black).
std::vector<LightGroup> lightGroups(const Scene& scene);

// The scene lit by one group alone: the other lights removed, the other emitters made black
// (they stay as geometry, so shadows and reflections are unchanged).
Scene sceneLitBy(const Scene& scene, const LightGroup& group);

// The EXR channel of a group's layer: "light.NAME.R" for c = 'R' (and G, B) for a light,
// "emitter.NAME.R" for an emissive object (a light and an object may share a name).
std::string lightLayerChannel(const LightGroup& group, char c);

// Per-group RGB weights that turn layers rendered for `rendered` into the image of `current`,
// when the two scenes differ at most in the emission of their lights and emitters (intensity,
// irradiance, photometric values, emitter radiance); nothing when anything else differs
// (geometry, a material's reflectance, a light moved, added or removed, the camera), or when a
// group that was black is lit now (its layer holds nothing to scale).
std::optional<std::vector<Rgb>> layerWeights(const Scene& rendered, const Scene& current);

// The image of the layers weighted: R, G, B = sum over groups of weight * layer. `image` must
// carry the layers of `groups` (lightLayerChannel); other channels are kept.
void mixLightLayers(Image& image, const std::vector<LightGroup>& groups, const std::vector<Rgb>& weights);

}  // namespace lucerna
