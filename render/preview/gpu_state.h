#pragma once
// Private to the preview's sources (preview.cpp: scene and VPLs; direct_lights.cpp and
// interleaved_vpls.cpp: their upload; frame_passes.cpp: the passes):
// the GL objects and CPU-side data behind Preview, and the GPU buffer layouts the shaders mirror.

#include "core/daylight/daylight.h"
#include "render/preview/gl_objects.h"
#include "render/preview/per_light_vpls.h"
#include "render/preview/shadow_maps.h"
#include "render/preview/preview.h"
#include "render/trace/lights/light_tree.h"
#include "render/trace/render_scene.h"

#include <array>
#include <chrono>
#include <map>
#include <memory>
#include <vector>

namespace lucerna {

namespace preview_detail {

using Clock = std::chrono::steady_clock;

// GPU layouts (std430), mirrored by the shaders.
struct GpuMaterial { float albedoKind[4], specularAlpha[4], radiance[4]; };
struct GpuVpl { float positionIndex[4], normalAlpha[4], incident[4], power[4], albedo[4], specular[4]; };
struct GpuLight { float positionKind[4], directionCosCone[4], intensityCosFalloff[4], normalShadow[4]; };
// A pane triangle for the VPLs' light (shade_vpl.frag's Pane): a corner, its two edges, its
// transmittance.
struct GpuPane { float p0[4], e1[4], e2[4], transmittance[4]; };
// Pane triangles the VPL shading tests each VPL's light against (beyond, it goes unattenuated).
constexpr int kMaxVplPanes = 64;
// One of the sky's directions (lights.glsl's SkyLight): toward it and its map's layer, its
// irradiance, its map's matrix (column-major).
struct GpuSkyLight { float towardLayer[4], irradiance[4], shadow[16]; };

inline void put(float* dst, const V3f& v, float w) { dst[0] = v.x; dst[1] = v.y; dst[2] = v.z; dst[3] = w; }
inline void put(float* dst, const Rgb& v, float w) { dst[0] = v.x; dst[1] = v.y; dst[2] = v.z; dst[3] = w; }

inline float materialKind(MaterialType t) {
    switch (t) {
    case MaterialType::Diffuse:
    case MaterialType::Glossy: return 1.0f;
    case MaterialType::Emitter: return 2.0f;
    case MaterialType::Glazing: return 4.0f;  // never in the G-buffer: seen through (glazing.frag)
    default: return 3.0f;  // mirror, glass: no preview model, drawn black
    }
}

inline int roundUp(int v, int multiple) { return (v + multiple - 1) / multiple * multiple; }

// Per light, the VPLs it gave: lightIndex -1 is all emissive triangles together, -2 a set given
// by setVpls, -3 the MIR set of all lights, kAllLights one instant radiosity set of all lights,
// kDaylightSet the sun's and the sky's.
constexpr int kAllLights = -4;
constexpr int kDaylightSet = -5;
struct LightVpls {
    int lightIndex = -1;
    int count = 0;
    VplSet vpls;
};

inline GLint loc(const gl::Program& p, const char* name) { return glGetUniformLocation(p.id(), name); }
inline void setInt(const gl::Program& p, const char* n, int v) { glProgramUniform1i(p.id(), loc(p, n), v); }
inline void setFloat(const gl::Program& p, const char* n, float v) { glProgramUniform1f(p.id(), loc(p, n), v); }
inline void setIvec2(const gl::Program& p, const char* n, int a, int b) { glProgramUniform2i(p.id(), loc(p, n), a, b); }
inline void setVec3(const gl::Program& p, const char* n, const V3f& v) { glProgramUniform3f(p.id(), loc(p, n), v.x, v.y, v.z); }

// Bytes from one per-sub-buffer uniform block to the next: blockBytes rounded up to the offset
// alignment GL asks of glBindBufferRange.
inline size_t uniformBlockStride(size_t blockBytes) {
    GLint align = 1;
    glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
    return size_t(roundUp(int(blockBytes), std::max(align, 1)));
}

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
    // Panes (glazing.frag) seen by the camera (with gbuffer.vert) and by the directional maps.
    gl::Program glazingProgram, glazingShadowProgram;
    gl::VertexArray emptyVao, sceneVao;
    gl::Buffer vertices, triangles, materials, vplBuffer, tileVplBlocks, lightBuffer, shadowCentres;
    // The opaque triangles first, then the panes (glazing), which the G-buffer and the shadow
    // maps leave out: the camera sees through them, and they cast no shadow.
    GLsizei vertexCount = 0, opaqueVertexCount = 0;
    bool glazing = false;  // the scene has panes
    // The pane triangles a VPL's light crosses on its way to a pixel are tested one by one
    // (shade_vpl.frag's VPL_PANES): vplPaneCount of them in paneTriangles, 0 past kMaxVplPanes
    // (paneNote says so).
    gl::Buffer paneTriangles;
    int vplPaneCount = 0;
    std::string paneNote;

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
    uint64_t seed = 1;      // the VPLs' and area samples' (regenerate)
    uint64_t dealSeed = 1;  // how VPLs and lights are dealt to the sub-buffers (redeal)

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
    // Shadow maps. The VPLs' and the area samples' low-resolution maps are drawn again for every
    // fresh set, from the proxy (shadow_proxy.h; the scene itself when it is small); the delta
    // lights' from the scene.
    gl::VertexArray proxyVao;
    gl::Buffer proxyVertices;
    preview_detail::ShadowCaster sceneCaster, proxyCaster;
    preview_detail::CubeShadowSet lightShadows, vplShadows;
    preview_detail::DirectionalShadows dirShadows;
    // The panes, drawn into the directional maps' transmittance layers (render/preview/shadow_maps.h)
    // and into viewTransmittance: what the camera sees through them (product of transmittances).
    preview_detail::ShadowCaster paneCaster;
    gl::Texture viewTransmittance;
    gl::Framebuffer viewTransmittanceFbo;
    // Daylight (SPEC.md section 5, render/preview/daylight_samples.h): the scene's sun and sky,
    // the directional lights' and the sun's maps' matrices, and the sky's directions with their
    // maps (direct_lights.cpp, uploadSkyLights): all of them in skyLightBuffer, and with
    // interleaving skyPerTile of them a sub-buffer as uniform blocks skyBlockStride apart.
    Daylight daylight;
    gl::Buffer dirMatrices;
    preview_detail::DirectionalShadows skyShadows;
    gl::Buffer skyLightBuffer, tileSkyBlocks;
    // Reads a depth map's texels as numbers (no comparison, nearest): the sun's, whose texture
    // compares for the other directional lights' PCF.
    gl::Sampler rawDepth;
    int skyLightCount = 0, skyPerTile = 0;
    GLintptr skyBlockStride = 0;
    gl::Texture luminaireTables;  // luminaire_textures.h: a layer per distinct distribution
    // directLights: [0, shadedHere) shaded in full by the direct pass; [firstInterleaved,
    // firstInterleaved + interleavedCount) dealt to the sub-buffers and shaded with the VPLs:
    // the delta lights when there are many (padded with dark lights to a multiple of n m), then
    // the area samples [firstAreaLight, firstAreaLight + areaLightCount).
    int shadedHere = 0, firstInterleaved = 0, interleavedCount = 0;
    int firstAreaLight = 0, areaLightCount = 0;
    bool interleavedDeltas = false;
    // With interleavedDeltas, the delta lights each block of the image shades in full
    // (light_blocks.h), chosen every frame from what the block sees (chooseLightsPerBlock):
    // directLights from firstBlockLight on holds every delta light (deltaTree: the light tree
    // over them), blockLights lightsPerBlock indices a block (-1: none), dealtAt each delta light's
    // place among the dealt lights (from firstInterleaved; -1: not dealt this frame). Blocks are
    // lightBlockSize pixels, the grid shifted by lightBlockOffset with each deal; lightBlockSize
    // 0: no blocks this frame.
    int firstBlockLight = 0, lightsPerBlock = 0;
    int lightBlockSize = 0, lightBlocksX = 0, lightBlocksY = 0;
    int lightBlockOffsetX = 0, lightBlockOffsetY = 0;
    LightTree deltaTree;
    gl::Buffer blockLights, dealtAt;
    // The blocks' boxes (light_block_bounds.frag): lowest and highest position seen, a texel of
    // lightBlocksX x lightBlocksY a block.
    gl::Program blockBoundsProgram;
    std::array<gl::Texture, 2> blockBoxes;
    gl::Framebuffer blockBoxFbo;
    int shadedKinds = 0, interleavedKinds = 0;  // bit k: a light of GpuLight kind k in that range
    // What was given up to stay within the GPU's limits (Preview::degradation), by cause.
    std::string vplNote, lightNote;
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
    bool vplVisibility = false;  // the VPLs have shadow maps this frame
    bool glossyScene = false;  // any glossy material with a specular lobe
    // The VPL shading and direct programs, compiled for their switches as needed, by file and
    // #defines (frame_passes.cpp, programVariant).
    std::map<std::string, gl::Program> programVariants;
    int uploadedVplCount = 0;
    PreviewTimings timings;
    std::string degradation;  // Preview::degradation()

    int splitW() const { return subW * patternX; }
    int splitH() const { return subH * patternY; }
};

namespace preview_detail {
// Direct lights (direct_lights.cpp): the light buffer's ranges above and their shadow maps.
void uploadLights(Preview::State& st, const PreviewSettings& settings);
// With interleavedDeltas, after the G-buffer: each block's lights shaded in full (light_blocks.h),
// from the boxes of what the blocks see, into blockLights and blockMasks (direct_lights.cpp).
void chooseLightsPerBlock(Preview::State& st);
// VPLs (interleaved_vpls.cpp): the sets dealt to the sub-buffers (tiles, vplBuffer,
// tileVplBlocks) and their shadow maps.
void uploadVpls(Preview::State& st, const PreviewSettings& settings);
}  // namespace preview_detail

}  // namespace lucerna
