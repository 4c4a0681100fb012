#pragma once
// The glTF 2.0 model the import tests write (test_model_import, test_model_import_window): five
// squares with the five SPEC materials, a point light and a spot, a camera.

#include "import_test_helpers.h"

#include <QByteArray>
#include <QFile>
#include <QTemporaryDir>

#include <cstdint>

namespace lucerna::test {

// A unit square in the xy plane facing -z (two triangles), as a base64 glTF buffer: four float
// positions, then six uint16 indices.
inline QByteArray squareBuffer() {
    const float p[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const uint16_t i[6] = {0, 2, 1, 0, 3, 2};
    QByteArray b(reinterpret_cast<const char*>(p), sizeof p);
    b.append(reinterpret_cast<const char*>(i), sizeof i);
    return b;
}

// Five squares (one per material) placed by node transforms, a point light of 100 cd and a red
// spot pointing down, a camera. Coordinates in metres; inside the Cornell box (0.555 m wide),
// in front of its blocks, when imported into it.
inline QByteArray gltfText() {
    const QByteArray buffer = squareBuffer();
    QByteArray mesh;
    for (int k = 0; k < 5; ++k)
        mesh += QByteArray(k ? "," : "") + R"({"name": "M)" + QByteArray::number(k) +
                R"(", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": )" + QByteArray::number(k) + "}]}";
    return R"({
  "asset": {"version": "2.0", "generator": "test_model_import"},
  "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_transmission", "KHR_materials_emissive_strength"],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"name": "Bulb", "type": "point", "intensity": 100},
    {"name": "Spot", "type": "spot", "color": [1, 0.5, 0.5], "intensity": 50,
     "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}}]}},
  "scene": 0,
  "scenes": [{"nodes": [0, 1, 2, 3, 4, 5, 6, 7]}],
  "nodes": [
    {"name": "Plain", "mesh": 0, "translation": [0.1, 0.05, 0.03], "scale": [0.15, 0.15, 1]},
    {"name": "Chrome", "mesh": 1, "translation": [0.3, 0.05, 0.03], "scale": [0.15, 0.15, 1]},
    {"name": "Glass", "mesh": 2, "translation": [0.1, 0.3, 0.1], "scale": [0.1, 0.1, 1]},
    {"name": "Lamp", "mesh": 3, "translation": [0.3, 0.3, 0.1], "scale": [0.1, 0.1, 1]},
    {"name": "Satin", "mesh": 4, "translation": [0.4, 0.3, 0.1], "scale": [0.1, 0.1, 1]},
    {"name": "Bulb", "translation": [0.278, 0.4, 0.25], "extensions": {"KHR_lights_punctual": {"light": 0}}},
    {"name": "Spot", "translation": [0.2, 0.5, 0.25], "rotation": [-0.70710678, 0, 0, 0.70710678],
     "extensions": {"KHR_lights_punctual": {"light": 1}}},
    {"name": "Cam", "camera": 0, "translation": [0.278, 0.273, -0.8]}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.01}}],
  "materials": [
    {"name": "Plain", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.8, 0.3, 1], "metallicFactor": 0, "roughnessFactor": 1}},
    {"name": "Chrome", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.7, 1], "metallicFactor": 1, "roughnessFactor": 0}},
    {"name": "Glass", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0, "roughnessFactor": 0},
     "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}}},
    {"name": "Lamp", "emissiveFactor": [1, 0.5, 0.25], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 100}}},
    {"name": "Satin", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0, "roughnessFactor": 0.4}}],
  "meshes": [)" + mesh + R"(],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,)" + buffer.toBase64() + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})";
}

// The model as `model.gltf` in `dir`, written on the first call: its path.
inline QString gltfModelPath(const QTemporaryDir& dir) {
    const QString path = dir.filePath("model.gltf");
    if (!QFile::exists(path)) writeFile(path, gltfText());
    return path;
}

}  // namespace lucerna::test
