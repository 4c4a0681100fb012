#pragma once
// glTF 2.0 material extensions that Assimp (Debian 12's 5.2) does not pass on:
// KHR_materials_emissive_strength and KHR_materials_ior, read from the file's JSON (a .gltf, or
// the JSON chunk of a .glb).

#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct GltfMaterialExtensions {
    std::optional<double> emissiveStrength;  // KHR_materials_emissive_strength
    std::optional<double> ior;               // KHR_materials_ior
};

// One entry per material of the file, in its order (Assimp keeps that order). Empty when the
// file cannot be read as glTF JSON: the caller then goes on without the extensions.
std::vector<GltfMaterialExtensions> readGltfMaterialExtensions(const std::string& path);

}  // namespace lucerna
