#pragma once
// Light groups for per-light layers (issue 7): the converged image is linear in the emission of
// each light, so a render kept as one layer per light can be dimmed, switched and recoloured
// afterwards by weighting the layers, with no new render. A layer's group is one light of the
// scene that belongs to no group (point, spot, directional, luminaire), every light of one of the
// scene's groups together (the lights' "group" key, issue 19), or one emissive object. Lights
// switched off have no layer.

#include "core/image/image.h"
#include "core/scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct LightGroup {
    std::string name;       // the light's, the scene group's or the object's name in the scene
    bool isObject = false;  // an emissive object (else Scene::lights[index])
    int index = 0;          // into Scene::lights or Scene::objects (a scene group: its first light)
    // A scene group: the indices of its lights (switched on), in file order; empty otherwise.
    std::vector<int> members;
    bool isSceneGroup() const { return !members.empty(); }
};

// The most layers a layered render takes: each is a render of its own (its own acceleration
// structure and film), so 10,000 lights cannot each have one. Past it makeLayeredBackend refuses
// (lightLayerLimitMessage); grouping lights makes one layer of each group.
inline constexpr size_t kMaxLightLayers = 64;

// The lights that are switched on, in file order, each alone or in its scene group (a group
// stands where its first light is), then every object whose material emits (non-black).
std::vector<LightGroup> lightGroups(const Scene& scene);

// The one line that refuses a layered render of `layers` layers (more than kMaxLightLayers).
std::string lightLayerLimitMessage(size_t layers);

// The scene lit by one group alone: the other lights removed (a scene group keeps all its lights
// that are on), the other emitters made black (they stay as geometry, so shadows and reflections
// are unchanged).
Scene sceneLitBy(const Scene& scene, const LightGroup& group);

// The EXR channel of a group's layer: "light.NAME.R" for c = 'R' (and G, B) for a light,
// "group.NAME.R" for a scene group, "emitter.NAME.R" for an emissive object (a light, a group and
// an object may share a name).
std::string lightLayerChannel(const LightGroup& group, char c);

// Per-group RGB weights that turn layers rendered for `rendered` into the image of `current`,
// when the two scenes differ at most in the emission of their lights and emitters (intensity,
// irradiance, photometric values, emitter radiance, switching off) and every light of a scene
// group changed by the same factor; nothing when anything else differs (geometry, a material's
// reflectance, a light moved, added or removed, the camera), when a group that was black is lit
// now (its layer holds nothing to scale), when a light switched off is on now, or when the
// lights of one layer changed by different factors.
std::optional<std::vector<Rgb>> layerWeights(const Scene& rendered, const Scene& current);

// The image of the layers weighted: R, G, B = sum over groups of weight * layer. `image` must
// carry the layers of `groups` (lightLayerChannel); other channels are kept.
void mixLightLayers(Image& image, const std::vector<LightGroup>& groups, const std::vector<Rgb>& weights);

}  // namespace lucerna
