#include "render/trace/surface_layers.h"

#include <limits>
#include <sstream>
#include <stdexcept>

namespace lucerna {

namespace {
// What a surface reflects at most, per channel, whatever the directions: the value compositors
// and denoisers expect in an albedo layer.
Rgb layerAlbedo(const Material& m) {
    switch (m.type) {
    case MaterialType::Diffuse:
    case MaterialType::Glossy: return toFloat(m.albedo);
    case MaterialType::Mirror: return toFloat(m.reflectance);
    case MaterialType::Dielectric: return Rgb(1, 1, 1);
    case MaterialType::Emitter: return Rgb(0, 0, 0);
    case MaterialType::Glazing: return toFloat(m.transmittance);  // never the first surface: panes are crossed
    }
    return Rgb(0, 0, 0);
}
}  // namespace

SurfaceLayers traceSurfaceLayers(const RenderScene& scene) {
    const Sensor& camera = scene.camera();
    SurfaceLayers out;
    out.width = camera.width();
    out.height = camera.height();
    const size_t n = size_t(out.width) * size_t(out.height);
    out.albedo.assign(n, Rgb(0, 0, 0));
    out.normal.assign(n, V3f(0, 0, 0));
    out.depth.assign(n, std::numeric_limits<float>::infinity());
    std::vector<Rgb> albedoOf;
    for (const Material& m : scene.scene().materials) albedoOf.push_back(layerAlbedo(m));

    // A row at a time as coherent packets: the rays of a row share their origin.
    std::vector<Ray> rays(size_t(out.width));
    std::vector<RayHit> hits(size_t(out.width));
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) rays[size_t(x)] = camera.ray(float(x) + 0.5f, float(y) + 0.5f);
        scene.accel().intersectCoherent(rays.data(), hits.data(), rays.size());
        for (int x = 0; x < out.width; ++x) {
            const RayHit& h = hits[size_t(x)];
            if (!h.found()) continue;
            const size_t i = size_t(y) * size_t(out.width) + size_t(x);
            const SurfacePoint sp = scene.surfacePoint(h.triangle, h.b1, h.b2);
            out.albedo[i] = albedoOf[sp.material];
            out.normal[i] = sp.ng;
            out.depth[i] = h.t;  // camera.ray() directions are unit: t is a distance
        }
    }
    return out;
}

std::optional<unsigned> parseLayerList(const std::string& list, std::string* error) {
    unsigned bits = 0;
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        if (name == "albedo") bits |= kAlbedoLayer;
        else if (name == "normal") bits |= kNormalLayer;
        else if (name == "depth") bits |= kDepthLayer;
        else if (name == "illuminance") bits |= kIlluminanceLayer;
        else if (name == "lights") bits |= kLightLayers;
        else if (name == "all") bits |= kAllLayers;
        else {
            if (error) *error = "unknown layer '" + name + "' (available: albedo, normal, depth, illuminance, lights, all)";
            return std::nullopt;
        }
    }
    if (bits == 0) {
        if (error) *error = "no layer named in '" + list + "' (available: albedo, normal, depth, illuminance, lights, all)";
        return std::nullopt;
    }
    return bits;
}

void addSurfaceLayers(Image& image, const SurfaceLayers& layers, unsigned which) {
    if (layers.width != image.width || layers.height != image.height)
        throw std::invalid_argument("surface layers and image differ in size");
    const size_t n = image.pixelCount();
    const auto triple = [&](const char* layer, const char* names, const auto& get) {
        for (int c = 0; c < 3; ++c) {
            std::vector<float>& data = image.channels[std::string(layer) + "." + names[c]];
            data.resize(n);
            for (size_t i = 0; i < n; ++i) data[i] = get(i)[c];
        }
    };
    if (which & kAlbedoLayer) triple("albedo", "RGB", [&](size_t i) { return layers.albedo[i]; });
    if (which & kNormalLayer) triple("normal", "XYZ", [&](size_t i) { return layers.normal[i]; });
    if (which & kDepthLayer) image.channels["depth.Z"] = layers.depth;
}

void addSurfaceLayers(Image& image, const SceneSnapshot& scene, unsigned which) {
    const RenderScene compiled(scene, image.width, image.height);
    addSurfaceLayers(image, traceSurfaceLayers(compiled), which);
}

}  // namespace lucerna
