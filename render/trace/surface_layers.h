#pragma once
// The first visible surface under each pixel, for the extra EXR layers of SPEC.md section 3:
// albedo.R/G/B, normal.X/Y/Z and depth.Z. One camera ray through each pixel's centre (not a box
// filter as for radiance: an average of normals or depths across an edge would describe no
// surface at all).

#include "core/image/image.h"
#include "render/trace/render_scene.h"

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct SurfaceLayers {
    int width = 0, height = 0;
    // Per pixel, row-major from the top-left as Image::pixels. Where the ray hits nothing:
    // albedo 0, normal 0, depth +infinity.
    std::vector<Rgb> albedo;    // diffuse/glossy: albedo; mirror: reflectance; dielectric: 1; emitter: 0
    std::vector<V3f> normal;    // unit world-space geometric normal of the front face (SPEC.md winding)
    std::vector<float> depth;   // distance from the camera along the unit ray, in scene units
};

// Traces the layers at the RenderScene's camera resolution. Never throws.
SurfaceLayers traceSurfaceLayers(const RenderScene& scene);

// Which layers go into an image (bit flags). kAllLayers is the three surface layers; the
// illuminance layer (render/photometry/illuminance_layer.h) is a Monte Carlo estimate that costs
// as much as a render, so it is asked for by name only, and addSurfaceLayers ignores its bit.
// The per-light layers (render/backend/light_layers) are rendered by the backend itself.
enum LayerBits : unsigned {
    kAlbedoLayer = 1u, kNormalLayer = 2u, kDepthLayer = 4u, kAllLayers = 7u, kIlluminanceLayer = 8u,
    kLightLayers = 16u
};

// "albedo,normal,depth,illuminance,lights" (any non-empty subset, any order; "all" for the first
// three) to bits. Returns
// nothing and sets *error to a one-line reason on an unknown or empty name.
std::optional<unsigned> parseLayerList(const std::string& list, std::string* error);

// Adds the chosen layers to `image` as the channels albedo.R/G/B, normal.X/Y/Z, depth.Z. The
// layers must have the image's size.
void addSurfaceLayers(Image& image, const SurfaceLayers& layers, unsigned which);

// The layers of `scene` traced at the image's size and added to it (a RenderScene is built for
// the purpose). Throws std::runtime_error when the scene cannot be compiled for tracing.
void addSurfaceLayers(Image& image, const SceneSnapshot& scene, unsigned which = kAllLayers);

}  // namespace lucerna
