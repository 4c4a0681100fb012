#pragma once
// Private to the preview's sources (preview.cpp: scene and VPLs; frame_passes.cpp: the passes):
// the GL objects and CPU-side data behind Preview, and the GPU buffer layouts the shaders mirror.

#include "render/preview/gl_objects.h"
#include "render/preview/per_light_vpls.h"
#include "render/preview/preview.h"
#include "render/trace/render_scene.h"

#include <array>
#include <chrono>
#include <map>
#include <memory>
#include <vector>

namespace lucerna {

namespace preview_detail {

using Clock = std::chrono::steady_clock;

// A 4x4 matrix for column vectors, stored column-major as GLSL expects.
struct Mat4 {
    std::array<float, 16> m{};
    float& at(int row, int col) { return m[size_t(col * 4 + row)]; }
    void setRow(int row, const V3f& v, float w) {
        at(row, 0) = v.x;
        at(row, 1) = v.y;
        at(row, 2) = v.z;
        at(row, 3) = w;
    }
};

// The six cube faces' view-projections for a light at the origin, in GL's cube map order and
// orientation, so that texture(samplerCubeArray, vec4(dir, i)) finds what was drawn along dir.
inline std::array<Mat4, 6> cubeFaceMatrices(float nearZ, float farZ) {
    const V3f fwd[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const V3f up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    std::array<Mat4, 6> out;
    const float a = (farZ + nearZ) / (farZ - nearZ), b = -2.0f * farZ * nearZ / (farZ - nearZ);
    for (int i = 0; i < 6; ++i) {
        const V3f f = fwd[i], s = f.cross(up[i]).normalized(), u = s.cross(f);
        // 90 degrees, aspect 1: x_c = s.p, y_c = u.p, w_c = f.p.
        out[i].setRow(0, s, 0);
        out[i].setRow(1, u, 0);
        out[i].setRow(2, f * a, b);
        out[i].setRow(3, f, 0);
    }
    return out;
}

// GPU layouts (std430), mirrored by the shaders.
struct GpuMaterial { float albedoKind[4], specularAlpha[4], radiance[4]; };
struct GpuVpl { float positionIndex[4], normalAlpha[4], incident[4], power[4], albedo[4], specular[4]; };
struct GpuLight { float positionKind[4], directionCosCone[4], intensityCosFalloff[4], normalShadow[4]; };

inline void put(float* dst, const V3f& v, float w) { dst[0] = v.x; dst[1] = v.y; dst[2] = v.z; dst[3] = w; }
inline void put(float* dst, const Rgb& v, float w) { dst[0] = v.x; dst[1] = v.y; dst[2] = v.z; dst[3] = w; }

inline float materialKind(MaterialType t) {
    switch (t) {
    case MaterialType::Diffuse:
    case MaterialType::Glossy: return 1.0f;
    case MaterialType::Emitter: return 2.0f;
    default: return 3.0f;  // mirror, glass: no preview model, drawn black
    }
}

inline int roundUp(int v, int multiple) { return (v + multiple - 1) / multiple * multiple; }

// Per light, the VPLs it gave: lightIndex -1 is all emissive triangles together, -2 a set given
// by setVpls, -3 the MIR set of all lights.
struct LightVpls {
    int lightIndex = -1;
    int count = 0;
    VplSet vpls;
};

// A cube-map-array shadow target: distances in R32F, depth for the z-test, layered.
struct CubeShadows {
    gl::Texture distance, depth;
    gl::Framebuffer fbo;
    int size = 0, cubes = 0;
    // The centre (xyz, cube index) each cube was last drawn from, by cube index: a cube whose
    // centre has not moved is not drawn again. Valid while the geometry is the same: cleared by
    // a new scene (and by a new texture).
    std::vector<std::array<float, 4>> drawn;

    void ensure(int faceSize, int cubeCount) {
        if (faceSize == size && cubeCount <= cubes && distance) return;
        drawn.clear();
        size = faceSize;
        cubes = std::max(cubeCount, 1);
        distance = gl::makeTexture(GL_TEXTURE_CUBE_MAP_ARRAY);
        glTextureStorage3D(distance.id(), 1, GL_R32F, size, size, cubes * 6);
        glTextureParameteri(distance.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(distance.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        depth = gl::makeTexture(GL_TEXTURE_CUBE_MAP_ARRAY);
        glTextureStorage3D(depth.id(), 1, GL_DEPTH_COMPONENT32F, size, size, cubes * 6);
        fbo = gl::makeFramebuffer({distance.id()}, depth.id());
    }
};

// Orthographic depth maps of the directional lights, one layer each, compared in the lookup.
struct DirectionalShadows {
    static constexpr int kMaxLights = 4;  // direct.frag's MAX_DIRECTIONAL_SHADOWS
    gl::Texture depth;
    gl::Framebuffer fbo;
    int size = 0, layers = 0;
    std::vector<Mat4> matrices;

    void ensure(int mapSize, int layerCount) {
        layerCount = std::max(layerCount, 1);  // always something bound to the sampler
        if (mapSize == size && layerCount <= layers && depth) return;
        size = mapSize;
        layers = layerCount;
        depth = gl::makeTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(depth.id(), 1, GL_DEPTH_COMPONENT32F, size, size, layers);
        glTextureParameteri(depth.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);  // 2 x 2 PCF
        glTextureParameteri(depth.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(depth.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(depth.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        fbo = gl::makeFramebuffer();
        glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
        glNamedFramebufferReadBuffer(fbo.id(), GL_NONE);
    }
};

inline GLint loc(const gl::Program& p, const char* name) { return glGetUniformLocation(p.id(), name); }
inline void setInt(const gl::Program& p, const char* n, int v) { glProgramUniform1i(p.id(), loc(p, n), v); }
inline void setFloat(const gl::Program& p, const char* n, float v) { glProgramUniform1f(p.id(), loc(p, n), v); }
inline void setIvec2(const gl::Program& p, const char* n, int a, int b) { glProgramUniform2i(p.id(), loc(p, n), a, b); }
inline void setVec3(const gl::Program& p, const char* n, const V3f& v) { glProgramUniform3f(p.id(), loc(p, n), v.x, v.y, v.z); }

inline void drawFullscreen(GLuint fbo, int w, int h) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, w, h);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

template <typename T>
void upload(gl::Buffer& buffer, const std::vector<T>& data) {
    // Fresh storage each time: sizes change with the scene, and immutable storage cannot grow.
    buffer = gl::makeBuffer();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(std::max<size_t>(data.size() * sizeof(T), 16)),
                         data.empty() ? nullptr : data.data(), 0);
}

}  // namespace preview_detail

struct Preview::State {
    std::string shaderDir;
    gl::Program gbufferProgram, splitProgram, blurProgram, shadowProgram, dirShadowProgram;
    gl::VertexArray emptyVao, sceneVao;
    gl::Buffer vertices, triangles, materials, vplBuffer, tileVplBlocks, lightBuffer, shadowCentres;
    GLsizei vertexCount = 0;

    // Scene.
    SceneSnapshot snapshot;
    std::unique_ptr<RenderScene> scene;
    Camera camera;
    int width = 0, height = 0;
    std::vector<DeltaLight> deltas;  // by scene light index
    std::vector<preview_detail::LightVpls> sets;
    bool customVpls = false;
    int generations = 0;
    std::vector<preview_detail::GpuLight> directLights;
    bool vplsDirty = true, lightsDirty = true;
    uint64_t seed = 1;

    // Frame targets.
    int targetW = 0, targetH = 0, patternX = 0, patternY = 0, block = 0;
    int subW = 0, subH = 0;
    // G-buffer (gbuffer.glsl's two attachments), its split layout with the discontinuity buffer
    // third (split.frag), and the two-pass split's intermediate; the VPL shading pass's output in
    // split layout (indirectSplit) or, without interleaving, in image layout (indirect);
    // blurTemp: gathered and blurred horizontally.
    std::array<gl::Texture, 2> g;
    std::array<gl::Texture, 3> s, t;
    gl::Texture depth, indirectSplit, indirect, blurTemp, final;
    gl::Framebuffer gFbo, sFbo, tFbo, indirectSplitFbo, indirectFbo, blurFbo, finalFbo;
    preview_detail::CubeShadows directShadows;
    // VPL visibility: cube map arrays hold at most GL_MAX_ARRAY_TEXTURE_LAYERS / 6 cubes (341 on
    // llvmpipe), so the VPLs' maps are spread over up to kVplShadowChunks arrays
    // (shade_vpl.frag picks the array by VPL index / vplCubesPerChunk).
    static constexpr int kVplShadowChunks = 4;
    std::array<preview_detail::CubeShadows, kVplShadowChunks> vplShadows;
    int vplCubesPerChunk = 1;
    preview_detail::DirectionalShadows dirShadows;
    gl::Texture luminaireTables;  // luminaire_textures.h: a layer per luminaire
    int directShadowCubes = 0;
    int firstAreaLight = 0, areaLightCount = 0;  // the area samples' range in directLights
    // The VPL shading pass draws each sub-buffer with its own VPLs: vplBuffer[first, first +
    // count), and with unrolledVpls > 0 the same VPLs as a uniform block at byte `blockOffset`
    // of tileVplBlocks (unrolledVpls of them, the last padded).
    struct TileVpls {
        int first = 0, count = 0;
        GLintptr blockOffset = 0;
    };
    std::vector<TileVpls> tiles;
    int unrolledVpls = 0;
    // Interleaved area samples: sub-buffer k's areaPerTile samples as a uniform block at byte
    // k * areaBlockStride of tileAreaBlocks (shade_vpl.frag's UNROLLED_AREA); 0: none, or more
    // than an unrolled body should hold (the shader loops over lightBuffer).
    gl::Buffer tileAreaBlocks;
    int areaPerTile = 0;
    GLintptr areaBlockStride = 0;
    int vplShadowChunks = 0;  // cube map arrays in use (0: VPL visibility off)
    bool glossyScene = false;  // any glossy material with a specular lobe
    int lightKinds = 0;  // bit k: a light of GpuLight kind k is in the light buffer
    // The VPL shading and direct programs, compiled for their switches as needed, by file and
    // #defines (frame_passes.cpp, programVariant).
    std::map<std::string, gl::Program> programVariants;
    int uploadedVplCount = 0;
    PreviewTimings timings;
    std::string degradation;  // Preview::degradation()

    int splitW() const { return subW * patternX; }
    int splitH() const { return subH * patternY; }
};

}  // namespace lucerna
