#include "core/mesh/gltf_material_extensions.h"

#include "core/scene/json_reader.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace lucerna {

namespace {
// The JSON text of a .gltf, or of a .glb's first chunk (header: magic, version, length; chunk:
// length, type "JSON", data). Empty when it is neither.
std::string jsonText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0) return bytes;
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    if (bytes.compare(16, 4, "JSON") != 0 || length > bytes.size() - 20) return {};
    return bytes.substr(20, length);
}

std::optional<double> number(const json::Value* object, const char* extension, const char* key) {
    const json::Value* ext = object ? object->find(extension) : nullptr;
    const json::Value* v = ext ? ext->find(key) : nullptr;
    if (v && v->type == json::Type::Number) return v->number;
    return std::nullopt;
}
}  // namespace

std::vector<GltfMaterialExtensions> readGltfMaterialExtensions(const std::string& path) {
    std::vector<GltfMaterialExtensions> out;
    try {
        const json::Value root = json::parse(jsonText(path));
        const json::Value* materials = root.find("materials");
        if (!materials || materials->type != json::Type::Array) return out;
        for (const json::Value& m : materials->array) {
            const json::Value* ext = m.find("extensions");
            out.push_back({number(ext, "KHR_materials_emissive_strength", "emissiveStrength"),
                           number(ext, "KHR_materials_ior", "ior")});
        }
    } catch (const std::exception&) {
        out.clear();  // Assimp read the file; only the extensions are lost
    }
    return out;
}

}  // namespace lucerna
