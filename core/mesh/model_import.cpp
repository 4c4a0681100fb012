#include "core/mesh/model_import.h"

#include "core/mesh/gltf_material_extensions.h"
#include "core/mesh/mesh_edges.h"
#include "core/mesh/obj_file.h"
#include "core/mesh/regular_files_only.h"
#include "core/message_text.h"
#include "core/regular_file.h"
#include "core/image/texture_average.h"

#include <assimp/GltfMaterial.h>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>

namespace lucerna {

namespace {

constexpr double kLumensPerWatt = 683.0;  // SPEC.md's photometric convention

std::string format(const char* fmt, double a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, a);
    return buf;
}
std::string rgbText(const Rgbd& c) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "[%.3g, %.3g, %.3g]", c.x, c.y, c.z);
    return buf;
}
double maxChannel(const Rgbd& c) { return std::max({c.x, c.y, c.z}); }
Rgbd clamp01(const Rgbd& c) {
    return Rgbd(std::clamp(c.x, 0.0, 1.0), std::clamp(c.y, 0.0, 1.0), std::clamp(c.z, 0.0, 1.0));
}

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// Assimp 5.2's OBJ importer has out-of-bounds reads and writes on malformed lines (oss-fuzz
// reports on ObjFileParser::getFace and ObjFileImporter::createVertexArray, fixed after 5.2.5).
// So an OBJ file is read by Lucerna's own reader first, and a line that reader refuses is refused
// here with its number. (The material libraries it names are guarded by RegularFilesOnly.)
void checkObjFile(const std::string& path) {
    try {
        std::ifstream in(path, std::ios::binary);
        readObjBytes(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(path + ": the file is too large to read into memory");
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

// Names unique across objects and lights together (SPEC.md), and materials apart: base, base-2, ...
class NameBook {
public:
    explicit NameBook(const Scene* scene) {
        if (!scene) return;
        for (const Object& o : scene->objects) things_.insert(o.name);
        for (const Light& l : scene->lights) things_.insert(l.name);
        for (const Material& m : scene->materials) materials_.insert(m.name);
    }
    std::string thing(const std::string& base) { return take(things_, base); }
    std::string material(const std::string& base) { return take(materials_, base); }

private:
    static std::string take(std::set<std::string>& used, const std::string& base) {
        std::string name = base;
        for (int i = 2; used.count(name); ++i) name = base + "-" + std::to_string(i);
        used.insert(name);
        return name;
    }
    std::set<std::string> things_, materials_;
};

// What decides whether a material lets light through: an emissive colour first (an emitter),
// then glTF's transmission factor or an opacity under 1 (OBJ `d`, glTF alpha unless OPAQUE).
struct Transparency {
    bool emissive = false;
    std::optional<float> transmission;
    double opacity = 1;
    bool seeThrough() const { return !emissive && ((transmission && *transmission > 0) || opacity < 0.999); }
};

struct Mapper {
    const aiScene& ai;
    bool gltf;
    std::string formatName;
    double toSceneUnits;  // metres per file unit after Assimp's own scaling / metres per scene unit
    NameBook names;
    ModelImport out;
    // (Assimp index, as glazing) -> scene name: a see-through material becomes glazing on an
    // open sheet and a dielectric on a closed mesh, so it may be mapped both ways.
    std::map<std::pair<unsigned, bool>, std::string> materialNames;
    std::vector<GltfMaterialExtensions> gltfExtensions;  // per glTF material (= Assimp index)
    aiMatrix4x4 axes;  // the file's axes to y up (FBX), before every node transform
    std::filesystem::path folder;  // the model's folder: texture paths are relative to it

    Transparency transparency(const aiMaterial& m) const;
    std::string mapMaterial(unsigned index, bool openSheet);
    std::optional<Rgbd> textureAverage(const aiMaterial& m, aiTextureType type) const;
    void visit(const aiNode& node, const aiMatrix4x4& parent);
    void mapLight(const aiLight& light);
};

std::optional<float> getFloat(const aiMaterial& m, const char* key, unsigned type, unsigned idx) {
    float v = 0;
    if (m.Get(key, type, idx, v) == aiReturn_SUCCESS) return v;
    return std::nullopt;
}
std::optional<Rgbd> getColour(const aiMaterial& m, const char* key, unsigned type, unsigned idx) {
    aiColor4D c;
    if (m.Get(key, type, idx, c) == aiReturn_SUCCESS) return Rgbd(c.r, c.g, c.b);
    return std::nullopt;
}

Transparency Mapper::transparency(const aiMaterial& m) const {
    Transparency t;
    t.emissive = maxChannel(getColour(m, AI_MATKEY_COLOR_EMISSIVE).value_or(Rgbd(0, 0, 0))) > 0;
    t.transmission = getFloat(m, AI_MATKEY_TRANSMISSION_FACTOR);
    aiString alphaMode;
    // glTF's OPAQUE mode says the base colour's alpha is to be ignored.
    const bool opaqueMode =
        gltf && m.Get(AI_MATKEY_GLTF_ALPHAMODE, alphaMode) == aiReturn_SUCCESS && std::string(alphaMode.C_Str()) == "OPAQUE";
    t.opacity = opaqueMode ? 1.0 : double(getFloat(m, AI_MATKEY_OPACITY).value_or(1.0f));
    return t;
}

// openSheet: the mesh has edges on a boundary (core/mesh/mesh_edges.h), so a see-through material on
// it is a thin pane.
std::string Mapper::mapMaterial(unsigned index, bool openSheet) {
    const aiMaterial& m = *ai.mMaterials[index];
    const Transparency see = transparency(m);
    const bool asGlazing = openSheet && see.seeThrough();
    if (auto it = materialNames.find({index, asGlazing}); it != materialNames.end()) return it->second;
    aiString aiName;
    std::string source = m.Get(AI_MATKEY_NAME, aiName) == aiReturn_SUCCESS ? aiName.C_Str() : "";
    if (source.empty()) source = "material-" + std::to_string(index);
    Material mat;
    mat.name = names.material(source);
    const std::string tag = "material '" + source + "': ";

    const std::optional<Rgbd> base = getColour(m, AI_MATKEY_BASE_COLOR);
    Rgbd colour = base ? *base : getColour(m, AI_MATKEY_COLOR_DIFFUSE).value_or(Rgbd(0.8, 0.8, 0.8));
    const std::optional<float> metallic = getFloat(m, AI_MATKEY_METALLIC_FACTOR);
    const std::optional<float> roughness = getFloat(m, AI_MATKEY_ROUGHNESS_FACTOR);
    const std::optional<float> transmission = see.transmission;
    const GltfMaterialExtensions ext = index < gltfExtensions.size() ? gltfExtensions[index] : GltfMaterialExtensions{};
    std::optional<double> refracti = ext.ior;
    if (!refracti)
        if (const std::optional<float> r = getFloat(m, AI_MATKEY_REFRACTI)) refracti = *r;
    const double opacity = see.opacity;
    const Rgbd emissive = getColour(m, AI_MATKEY_COLOR_EMISSIVE).value_or(Rgbd(0, 0, 0));
    const double emissiveStrength =
        ext.emissiveStrength.value_or(double(getFloat(m, AI_MATKEY_EMISSIVE_INTENSITY).value_or(1.0f)));

    // The base colour's texture becomes its average colour times the factor (one colour per
    // material); other textures are dropped.
    const aiTextureType colourTexture = gltf ? aiTextureType_BASE_COLOR : aiTextureType_DIFFUSE;
    if (m.GetTextureCount(colourTexture) > 0) {
        const char* label = gltf ? "baseColorTexture" : "diffuse texture";
        if (const std::optional<Rgbd> mean = textureAverage(m, colourTexture)) {
            colour = Rgbd(colour.x * mean->x, colour.y * mean->y, colour.z * mean->z);
            out.report.push_back(tag + label + " averaged to " + rgbText(*mean) + " (linear), times the factor");
        } else {
            out.report.push_back(tag + label + " could not be read, factor used");
        }
    }
    for (const auto& [type, label] : {std::pair{aiTextureType_METALNESS, "metallic texture"},
                                      std::pair{aiTextureType_DIFFUSE_ROUGHNESS, "roughness texture"},
                                      std::pair{aiTextureType_EMISSIVE, "emissive texture"},
                                      std::pair{aiTextureType_NORMALS, "normal map"},
                                      std::pair{aiTextureType_SPECULAR, "specular texture"},
                                      std::pair{aiTextureType_OPACITY, "opacity texture"}}) {
        if (m.GetTextureCount(type) > 0) out.report.push_back(tag + label + " ignored, factor used");
    }

    const double ior = refracti && *refracti > 1.0 ? *refracti : 1.5;
    const char* iorNote = refracti && *refracti > 1.0 ? "" : " (default)";
    if (maxChannel(emissive) > 0) {
        mat.type = MaterialType::Emitter;
        mat.radiance = emissive * emissiveStrength / kLumensPerWatt;
        out.report.push_back(tag + "emissive " + rgbText(emissive) + " x strength " + format("%g", emissiveStrength) +
                             " taken as cd/m^2 -> emitter radiance " + rgbText(mat.radiance) +
                             " W sr^-1 m^-2 (front face only; base colour ignored)");
    } else if (asGlazing) {
        // A pane: light crosses it straight (SPEC.md's glazing). glTF tints transmitted light by
        // the base colour, and the pane's two surfaces still reflect: a clear slab's
        // normal-incidence transmittance is (1 - R0) / (1 + R0), R0 = ((n - 1) / (n + 1))^2
        // (0.923 at n = 1.5). An opacity is what the author lets through, 1 - opacity, tinted by a
        // transmission filter (OBJ `Tf`) where there is one.
        mat.type = MaterialType::Glazing;
        std::string how;
        if (transmission && *transmission > 0) {
            const double r0 = (ior - 1) * (ior - 1) / ((ior + 1) * (ior + 1));
            const double t = *transmission * (1 - r0) / (1 + r0);
            mat.transmittance = clamp01(colour * t);
            how = "transmission " + format("%g", *transmission) + " x base colour " + rgbText(colour) + " x " +
                  format("%.3g", (1 - r0) / (1 + r0)) + " (the two surfaces' reflection at ior " + format("%g", ior) + iorNote + ")";
        } else {
            // A black filter is what some exporters write for "none".
            Rgbd filter = getColour(m, AI_MATKEY_COLOR_TRANSPARENT).value_or(Rgbd(1, 1, 1));
            if (!(maxChannel(filter) > 0)) filter = Rgbd(1, 1, 1);
            mat.transmittance = clamp01(filter * (1 - opacity));
            how = "1 - opacity " + format("%g", opacity);
            if (filter != Rgbd(1, 1, 1)) how += " x transmission filter " + rgbText(filter);
        }
        out.report.push_back(tag + "on an open sheet -> glazing, transmittance " + rgbText(mat.transmittance) + " = " + how);
    } else if (transmission && *transmission > 0) {
        mat.type = MaterialType::Dielectric;
        mat.ior = ior;
        out.report.push_back(tag + "transmission " + format("%g", *transmission) + " -> dielectric ior " +
                             format("%g", ior) + iorNote + " (colour, roughness and partial transmission dropped)");
    } else if (opacity < 0.999) {
        mat.type = MaterialType::Dielectric;
        mat.ior = ior;
        out.report.push_back(tag + "opacity " + format("%g", opacity) + " -> dielectric ior " + format("%g", ior) +
                             iorNote + " (clear glass; colour and partial opacity dropped)");
    } else if (metallic || roughness) {
        // glTF metallic-roughness.
        const double mtl = std::clamp(double(metallic.value_or(1.0f)), 0.0, 1.0);
        const double rough = std::clamp(double(roughness.value_or(1.0f)), 0.0, 1.0);
        const Rgbd c = clamp01(colour);
        if (mtl >= 0.9 && rough <= 0.1) {
            mat.type = MaterialType::Mirror;
            mat.reflectance = c;
            out.report.push_back(tag + "metallic " + format("%g", mtl) + ", roughness " + format("%g", rough) +
                                 " -> mirror, reflectance = base colour " + rgbText(c));
        } else if (rough < 0.6 || mtl >= 0.5) {
            mat.type = MaterialType::Glossy;
            mat.albedo = c * (1.0 - mtl);
            const Rgbd f0 = Rgbd(0.04, 0.04, 0.04) * (1.0 - mtl) + c * mtl;
            mat.specular = clamp01(f0);
            mat.roughness = std::clamp(rough * rough, 1e-3, 1.0);
            out.report.push_back(tag + "metallic " + format("%g", mtl) + ", roughness " + format("%g", rough) +
                                 " -> glossy: albedo = base*(1-metallic), specular = F0 " + rgbText(mat.specular) +
                                 " (no Fresnel), alpha = roughness^2 = " + format("%g", mat.roughness));
        } else {
            mat.type = MaterialType::Diffuse;
            mat.albedo = c;
            out.report.push_back(tag + "roughness " + format("%g", rough) + " -> diffuse (specular lobe dropped)");
        }
    } else {
        mat.type = MaterialType::Diffuse;
        mat.albedo = clamp01(colour);
        const Rgbd ks = getColour(m, AI_MATKEY_COLOR_SPECULAR).value_or(Rgbd(0, 0, 0));
        if (maxChannel(ks) > 0) out.report.push_back(tag + "specular " + rgbText(ks) + " ignored (diffuse from Kd)");
    }
    if (mat.type == MaterialType::Diffuse && maxChannel(colour) > 1.0)
        out.report.push_back(tag + "colour " + rgbText(colour) + " clamped to [0, 1]");
    out.materials.push_back(mat);
    materialNames[{index, asGlazing}] = mat.name;
    return mat.name;
}

std::optional<Rgbd> Mapper::textureAverage(const aiMaterial& m, aiTextureType type) const {
    aiString where;
    if (m.GetTexture(type, 0, &where) != aiReturn_SUCCESS) return std::nullopt;
    // Embedded ("*N", or a file name the importer kept inside): compressed bytes or BGRA texels.
    if (const aiTexture* t = ai.GetEmbeddedTexture(where.C_Str())) {
        if (!t->pcData) return std::nullopt;
        if (t->mHeight == 0) return averageImageColour(reinterpret_cast<const unsigned char*>(t->pcData), t->mWidth);
        return averageTexelColour(reinterpret_cast<const unsigned char*>(t->pcData), size_t(t->mWidth) * t->mHeight, true);
    }
    std::filesystem::path file(where.C_Str());
    if (file.is_relative()) file = folder / file;
    return averageImageFileColour(file.string());
}

V3d transformPoint(const aiMatrix4x4& t, const aiVector3D& p) {
    const aiVector3D q = t * p;
    return V3d(q.x, q.y, q.z);
}

void Mapper::visit(const aiNode& node, const aiMatrix4x4& parent) {
    const aiMatrix4x4 world = parent * node.mTransformation;
    // A mirroring transform turns faces inside out; SPEC.md's front face follows the winding.
    const bool flip = world.Determinant() < 0;
    for (unsigned k = 0; k < node.mNumMeshes; ++k) {
        const aiMesh& mesh = *ai.mMeshes[node.mMeshes[k]];
        Object obj;
        TriangleMesh& tm = obj.mesh.inlineMesh;
        tm.vertices.reserve(mesh.mNumVertices);
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            // Assimp reads coordinates in single precision: "nan" stays NaN and 1e39 becomes inf.
            // Neither may reach the scene (its loader refuses both), nor a point that the unit
            // conversion takes beyond single precision.
            const aiVector3D& a = mesh.mVertices[v];
            const V3d p = transformPoint(world, a) * toSceneUnits;
            if (!(std::abs(p.x) <= FLT_MAX && std::abs(p.y) <= FLT_MAX && std::abs(p.z) <= FLT_MAX)) {
                char xyz[100];
                std::snprintf(xyz, sizeof xyz, "(%g, %g, %g)", double(a.x), double(a.y), double(a.z));
                const bool finite = std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
                throw std::runtime_error("mesh '" + printableWord(mesh.mName.C_Str()) + "': vertex " + std::to_string(v) +
                                         " is " + xyz +
                                         (finite ? ", beyond single-precision range in the scene's unit"
                                                 : ": not a finite point (a coordinate is NaN, or too large for single precision)"));
            }
            tm.vertices.push_back(p);
        }
        size_t others = 0;
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) {
                ++others;
                continue;
            }
            const int a = int(face.mIndices[0]), b = int(face.mIndices[1]), c = int(face.mIndices[2]);
            tm.triangles.push_back(flip ? V3i(a, c, b) : V3i(a, b, c));
        }
        // The node names the object (a mesh may be instanced by several nodes); an unnamed node
        // lends the mesh's name.
        std::string base = node.mName.length && &node != ai.mRootNode ? node.mName.C_Str() : mesh.mName.C_Str();
        if (base.empty()) base = node.mName.length ? node.mName.C_Str() : "mesh";
        if (others) out.report.push_back("mesh '" + base + "': " + std::to_string(others) + " point/line primitives ignored");
        if (tm.triangles.empty()) continue;
        // One object per material group: several meshes of one node get the material's name too.
        // Edges are counted only where they decide something (a see-through material).
        const bool seeThrough = transparency(*ai.mMaterials[mesh.mMaterialIndex]).seeThrough();
        const size_t boundary = seeThrough ? boundaryEdgeCount(tm) : 0;
        const std::string materialName = mapMaterial(mesh.mMaterialIndex, boundary > 0);
        if (node.mNumMeshes > 1) base += "-" + materialName;
        obj.name = names.thing(base);
        if (seeThrough)
            out.report.push_back("object '" + obj.name + "': " +
                                 (boundary > 0 ? "an open sheet (" + std::to_string(boundary) +
                                                     " boundary edges) -> glazing '" + materialName + "'"
                                               : "a closed mesh -> dielectric '" + materialName + "'"));
        obj.material = materialName;
        obj.mesh.kind = MeshSource::Kind::Inline;
        out.triangles += tm.triangles.size();
        out.objects.push_back(std::move(obj));
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) visit(*node.mChildren[i], world);
}

aiMatrix4x4 nodeWorld(const aiNode* node, const aiMatrix4x4& axes) {
    aiMatrix4x4 t;
    for (; node; node = node->mParent) t = node->mTransformation * t;
    return axes * t;
}

// FBX files say which axis is up, forward and right (Assimp 5.2 leaves the conversion to the
// application): the rows map them to y, z and x.
std::optional<aiMatrix4x4> fbxAxes(const aiMetadata* meta) {
    if (!meta) return std::nullopt;
    int up = 1, upSign = 1, front = 2, frontSign = 1, coord = 0, coordSign = 1;
    if (!meta->Get("UpAxis", up)) return std::nullopt;
    meta->Get("UpAxisSign", upSign);
    meta->Get("FrontAxis", front);
    meta->Get("FrontAxisSign", frontSign);
    meta->Get("CoordAxis", coord);
    meta->Get("CoordAxisSign", coordSign);
    if (up < 0 || up > 2 || front < 0 || front > 2 || coord < 0 || coord > 2 || up == front || up == coord || front == coord)
        return std::nullopt;
    const auto axis = [](int i, int sign) {
        aiVector3D v(0, 0, 0);
        v[unsigned(i)] = sign < 0 ? -1.0f : 1.0f;
        return v;
    };
    const aiVector3D x = axis(coord, coordSign), y = axis(up, upSign), z = axis(front, frontSign);
    return aiMatrix4x4(x.x, x.y, x.z, 0, y.x, y.y, y.z, 0, z.x, z.y, z.z, 0, 0, 0, 0, 1);
}

void Mapper::mapLight(const aiLight& light) {
    const std::string source = light.mName.length ? light.mName.C_Str() : "light";
    const std::string tag = "light '" + source + "': ";
    const aiNode* node = ai.mRootNode->FindNode(light.mName);
    const aiMatrix4x4 world = nodeWorld(node, axes);
    const aiVector3D origin = world * light.mPosition;
    aiMatrix3x3 rot(world);
    aiVector3D dir = rot * light.mDirection;
    if (dir.Length() > 0) dir.Normalize(); else dir = aiVector3D(0, -1, 0);

    // Assimp bakes the intensity into the colour: for glTF it is candela (point, spot) or lux
    // (directional). Other formats state no photometric unit; the same reading is assumed.
    const Rgbd c(light.mColorDiffuse.r, light.mColorDiffuse.g, light.mColorDiffuse.b);
    const double y = luminance(c);
    const std::string unitNote = gltf ? "" : " (" + formatName + " states no photometric unit: assumed)";
    Light l;
    l.name = names.thing(source);
    l.position = V3d(origin.x, origin.y, origin.z) * toSceneUnits;
    l.direction = V3d(dir.x, dir.y, dir.z);
    switch (light.mType) {
    case aiLightSource_POINT:
    case aiLightSource_SPOT: {
        l.type = light.mType == aiLightSource_POINT ? LightType::Point : LightType::Spot;
        PhotometricSpec spec;
        spec.quantity = PhotometricSpec::Quantity::Candela;
        spec.value = std::max(0.0, y);
        if (y > 0 && (std::abs(c.x - c.y) > 1e-6 * y || std::abs(c.y - c.z) > 1e-6 * y)) spec.colour = c / y;
        std::string text = tag + (l.type == LightType::Point ? "point" : "spot") + " " + format("%g", spec.value) +
                           " cd" + unitNote;
        if (l.type == LightType::Spot) {
            // Assimp passes on each format's convention: glTF measures its cone angles from the
            // axis, COLLADA (falloff_angle) and FBX across the whole cone, so those are halved.
            // For COLLADA, Assimp widens the outer angle by a penumbra it makes up from the
            // falloff exponent; the format's cone ends at falloff_angle, so ours ends there too.
            const bool dae = formatName == "DAE";
            const double toHalfDeg = (gltf ? 1.0 : 0.5) * 180.0 / M_PI;
            const double outer =
                std::clamp(double(dae ? light.mAngleInnerCone : light.mAngleOuterCone) * toHalfDeg, 1e-3, 179.0);
            const double inner = dae ? 0.0 : double(light.mAngleInnerCone) * toHalfDeg;
            l.coneAngleDeg = outer;
            if (inner > 0 && inner < outer) l.falloffStartDeg = inner;
            text += ", cone " + format("%g", outer) + " deg" +
                    (l.falloffStartDeg ? ", falloff from " + format("%g", inner) + " deg (smoothstep in cos)" : "");
        }
        l.photometric = spec;
        l.intensity = photometricIntensity(spec, l.type == LightType::Point ? pointSolidAngle()
                                                                               : spotSolidAngle(l.coneAngleDeg, l.falloffStartDeg));
        if (light.mAttenuationConstant != 0 || light.mAttenuationLinear != 0)
            text += "; attenuation replaced by the inverse square law";
        out.report.push_back(text);
        break;
    }
    case aiLightSource_DIRECTIONAL:
        l.type = LightType::Directional;
        l.irradiance = Rgbd(std::max(0.0, c.x), std::max(0.0, c.y), std::max(0.0, c.z)) / kLumensPerWatt;
        out.report.push_back(tag + "directional " + format("%g", y) + " lx" + unitNote);
        break;
    default:
        out.report.push_back(tag + "type not supported (area or ambient), ignored");
        return;
    }
    out.lights.push_back(std::move(l));
}

}  // namespace

ModelImport importModelInProcess(const std::string& path, const ImportOptions& options) {
    if (const std::string kind = nonRegularFileKind(path); !kind.empty())
        throw std::runtime_error(path + ": not a regular file (" + kind + ")");
    const std::string ext = lowerExtension(path);
    if (ext == ".obj") checkObjFile(path);
    Assimp::Importer importer;
    auto guardedFiles = std::make_unique<RegularFilesOnly>();
    const RegularFilesOnly& files = *guardedFiles;
    importer.SetIOHandler(guardedFiles.release());  // Assimp's Importer owns its IO system
    // aiProcess_GlobalScale applies the file's own unit where the importer reports one (FBX's
    // UnitScaleFactor, in centimetres, becomes metres); COLLADA's <unit> is applied by its loader.
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                           aiProcess_GlobalScale | aiProcess_ValidateDataStructure;
    const aiScene* ai = importer.ReadFile(path, flags);
    if (!files.refusal().empty()) throw std::runtime_error(path + ": " + files.refusal());
    // Assimp calls a scene without meshes incomplete; one with lights alone is still worth having.
    if (!ai || !ai->mRootNode || ((ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) && ai->mNumLights == 0)) {
        std::string why = importer.GetErrorString();
        std::replace(why.begin(), why.end(), '\n', ' ');
        if (why.empty()) why = "the file holds no scene";
        throw std::runtime_error(path + ": " + why);
    }

    const bool gltf = ext == ".gltf" || ext == ".glb";
    const bool fbx = ext == ".fbx", dae = ext == ".dae";
    const bool unitless = !gltf && !fbx && !dae;
    const double fileMeters = unitless ? options.fileMetersPerUnit.value_or(1.0) : 1.0;
    std::string formatName = ext.empty() ? std::string("the file") : ext.substr(1);
    std::transform(formatName.begin(), formatName.end(), formatName.begin(), [](unsigned char c) { return char(std::toupper(c)); });

    Mapper mapper{*ai, gltf, formatName, fileMeters / options.sceneMetersPerUnit, NameBook(options.into), {}, {},
                  gltf ? readGltfMaterialExtensions(path) : std::vector<GltfMaterialExtensions>{}, aiMatrix4x4(),
                  std::filesystem::path(path).parent_path()};
    ModelImport& out = mapper.out;
    out.report.emplace_back();  // the summary, filled in below

    if (unitless) {
        out.report.push_back(formatName + " states no unit: " +
                             (options.fileMetersPerUnit ? format("%g m per unit as given", fileMeters)
                                                        : std::string("metres assumed")));
    } else if (fbx) {
        double cm = 0;
        float cmf = 0;
        if (ai->mMetaData && (ai->mMetaData->Get("UnitScaleFactor", cm) || (ai->mMetaData->Get("UnitScaleFactor", cmf) && (cm = cmf))))
            out.report.push_back(format("FBX unit: %g cm per unit, converted to metres", cm));
        else
            out.report.push_back("FBX unit: none stated, centimetres assumed by Assimp");
        if (const std::optional<aiMatrix4x4> axes = fbxAxes(ai->mMetaData)) {
            mapper.axes = *axes;
            if (!axes->IsIdentity()) out.report.push_back("FBX axes turned to y up");
        }
    } else if (dae) {
        out.report.push_back("COLLADA <unit> and up axis applied by the reader");
    }
    if (options.sceneMetersPerUnit != 1.0)
        out.report.push_back(format("coordinates converted to the scene's unit (%g m)", options.sceneMetersPerUnit));

    try {
        mapper.visit(*ai->mRootNode, mapper.axes);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
    for (unsigned i = 0; i < ai->mNumLights; ++i) mapper.mapLight(*ai->mLights[i]);
    for (unsigned i = 0; i < ai->mNumCameras; ++i)
        out.report.push_back(std::string("camera '") + ai->mCameras[i]->mName.C_Str() + "' ignored");
    if (ai->mNumAnimations) out.report.push_back(std::to_string(ai->mNumAnimations) + " animation(s) ignored");

    if (out.objects.empty() && out.lights.empty()) throw std::runtime_error(path + ": no triangles and no lights to import");
    out.report.front() = std::to_string(out.objects.size()) + " object(s), " + std::to_string(out.triangles) +
                         " triangles, " + std::to_string(out.materials.size()) + " material(s), " +
                         std::to_string(out.lights.size()) + " light(s) imported from " +
                         std::filesystem::path(path).filename().string();
    return out;
}

}  // namespace lucerna
