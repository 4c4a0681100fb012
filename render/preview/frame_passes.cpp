// The passes of one preview frame (Preview::render): shadow maps (only when lights or VPLs
// changed), G-buffer (with what the camera sees through panes), split (with the discontinuity
// buffer), interleaved VPL shading, gather with the horizontal blur, vertical blur with the
// direct light and the blend, read-back.

#include "core/daylight/sky_model.h"
#include "render/preview/gpu_state.h"
#include "render/preview/luminaire_textures.h"
#include "render/vpl/vpl_contribution.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace lucerna {

using namespace preview_detail;

namespace {

void ensureTargets(Preview::State& st, int w, int h, int n, int m, int block) {
    if (st.targetW == w && st.targetH == h && st.patternX == n && st.patternY == m && st.block == block && st.final)
        return;
    st.targetW = w;
    st.targetH = h;
    st.patternX = n;
    st.patternY = m;
    st.block = block;
    // A tile holds ceil(W / n) x ceil(H / m) texels, rounded up to whole blocks of the two-pass
    // split; the padding reads as "no surface".
    st.subW = roundUp((w + n - 1) / n, block);
    st.subH = roundUp((h + m - 1) / m, block);
    const int sw = st.splitW(), sh = st.splitH();
    for (int i = 0; i < 3; ++i) {  // gbuffer.glsl's two attachments; the split's discontinuity buffer
        const GLenum format = i == 0 ? GL_RGBA32F : i == 1 ? GL_RGBA32UI : GL_R8UI;
        if (i < 2) st.g[size_t(i)] = gl::makeTexture2D(format, w, h);
        st.s[size_t(i)] = gl::makeTexture2D(format, sw, sh);
        st.t[size_t(i)] = gl::makeTexture2D(format, sw, sh);
    }
    st.depth = gl::makeTexture2D(GL_DEPTH_COMPONENT32F, w, h);
    st.gFbo = gl::makeFramebuffer({st.g[0].id(), st.g[1].id()}, st.depth.id());
    st.sFbo = gl::makeFramebuffer({st.s[0].id(), st.s[1].id(), st.s[2].id()});
    st.tFbo = gl::makeFramebuffer({st.t[0].id(), st.t[1].id(), st.t[2].id()});
    st.indirectSplit = gl::makeTexture2D(GL_RGBA32F, sw, sh);
    st.indirectSplitFbo = gl::makeFramebuffer({st.indirectSplit.id()});
    st.indirect = gl::makeTexture2D(GL_RGBA32F, w, h);
    st.indirectFbo = gl::makeFramebuffer({st.indirect.id()});
    st.blurTemp = gl::makeTexture2D(GL_RGBA32F, w, h);
    st.blurFbo = gl::makeFramebuffer({st.blurTemp.id()});
    st.final = gl::makeTexture2D(GL_RGBA32F, w, h);
    st.viewTransmittance = gl::makeTexture2D(GL_RGBA16F, w, h);
    st.viewTransmittanceFbo = gl::makeFramebuffer({st.viewTransmittance.id()}, st.depth.id());
    st.finalFbo = gl::makeFramebuffer({st.final.id()});
    gl::checkErrors("preview targets");
}

// The SPEC.md pinhole projection: pixel (i, j) shows the raster point (i + jx, j + jy). Rows are
// stored top first (NDC y is flipped), so texel rows match Image rows.
Mat4 viewProjection(const Camera& camera, int w, int h, float jx, float jy, float nearZ, float farZ) {
    const V3d fd = (camera.target - camera.position).normalized();
    const V3d rd = fd.cross(camera.up).normalized();
    const V3d ud = rd.cross(fd);
    const float t = float(std::tan(radians(camera.fovYDeg) * 0.5));
    const float aspect = float(w) / float(h);
    const V3f f = toFloat(fd), r = toFloat(rd), u = toFloat(ud), e = toFloat(camera.position);
    const float ox = (1.0f - 2.0f * jx) / float(w), oy = (1.0f - 2.0f * jy) / float(h);
    const float a = (farZ + nearZ) / (farZ - nearZ), b = -2.0f * farZ * nearZ / (farZ - nearZ);
    Mat4 m;
    const V3f row0 = r / (t * aspect) + f * ox, row1 = -u / t + f * oy;
    m.setRow(0, row0, -row0.dot(e));
    m.setRow(1, row1, -row1.dot(e));
    m.setRow(2, f * a, -a * f.dot(e) + b);
    m.setRow(3, f, -f.dot(e));
    return m;
}

// A fragment program with these #defines (the shaders' compile-time switches), compiled the first
// time it is asked for.
const gl::Program& programVariant(Preview::State& st, const std::string& fragment, const std::string& defines) {
    auto [it, fresh] = st.programVariants.try_emplace(fragment + "\n" + defines);
    if (fresh) it->second = gl::loadProgram(st.shaderDir, "fullscreen.vert", fragment, {}, defines);
    return it->second;
}

std::string define(const char* name, int value) { return std::string("#define ") + name + " " + std::to_string(value) + "\n"; }

std::string lightKindDefines(const Preview::State& st, int kinds) {
    const auto has = [&](int kind) { return (kinds >> kind) & 1; };
    return define("SPOT", has(1)) + define("DIRECTIONAL", has(2)) + define("AREA", has(3)) + define("LUMINAIRE", has(4)) +
           define("GLAZING", st.glazing ? 1 : 0);
}

// The VPL shading program for the current tiles, settings and scene (shade_vpl.frag's switches).
const gl::Program& shadeProgram(Preview::State& st, bool interleavedLights, bool interleavedSky, bool findEdges,
                                bool fusedSplit) {
    std::string defines = define("VPL_VISIBILITY", st.vplVisibility ? 1 : 0) + define("GLOSSY", st.glossyScene ? 1 : 0) +
                          define("INTERLEAVED_LIGHTS", interleavedLights ? 1 : 0) + define("FIND_EDGES", findEdges ? 1 : 0) +
                          define("FUSED_SPLIT", fusedSplit ? 1 : 0) +
                          define("UNROLLED_AREA", interleavedLights ? st.areaPerTile : 0) +
                          define("SKY_PER_TILE", interleavedSky ? st.skyPerTile : 0) +
                          lightKindDefines(st, interleavedLights ? st.interleavedKinds : 0) +
                          define("VPL_PANES", st.vplPaneCount) + define("UNROLLED_VPLS", st.unrolledVpls) +
                          "#define FOR_EACH_TILE_VPL(STEP)";
    for (int k = 0; k < st.unrolledVpls; ++k) defines += " STEP(" + std::to_string(k) + ")";
    return programVariant(st, "shade_vpl.frag", defines);
}

// The direct pass's program for the lights it evaluates (direct.frag's switches).
const gl::Program& directProgram(Preview::State& st, bool lightLoop, bool skyLoop, bool blockLights) {
    return programVariant(st, "direct.frag",
                          define("LIGHT_LOOP", lightLoop ? 1 : 0) + define("SKY_LIGHTS", skyLoop ? 1 : 0) +
                              define("BLOCK_LIGHTS", blockLights ? 1 : 0) +
                              lightKindDefines(st, lightLoop || blockLights ? st.shadedKinds : 0));
}

// The uniforms of light_blocks.glsl.
void setBlockUniforms(const Preview::State& st, const gl::Program& p) {
    const int size = std::max(st.lightBlockSize, 1);
    setInt(p, "lightBlockSize", size);
    setIvec2(p, "lightBlockOffset", st.lightBlockOffsetX % size, st.lightBlockOffsetY % size);
    setInt(p, "lightBlocksX", st.lightBlocksX);
    setInt(p, "lightsPerBlock", st.lightsPerBlock);
    setInt(p, "firstBlockLight", st.firstBlockLight);
    setInt(p, "firstDealt", st.firstInterleaved);
    setIvec2(p, "dealPattern", st.patternX, st.patternY);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, st.dealtAt.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, st.blockLights.id());
}

// The uniforms and textures of lights.glsl.
void setLightUniforms(Preview::State& st, const gl::Program& p) {
    setFloat(p, "lightShadowBias", 0.02f);
    setFloat(p, "lightTexelAngle", 2.0f / float(std::max(st.lightShadows.faceSize(), 1)));
    setFloat(p, "areaShadowSlack", st.proxyCaster.slack);
    setInt(p, "lightCubesPerArray", st.lightShadows.perArray());
    // Two texels of the map along the normal, half a texel of depth (the map spans 2 radii).
    const float diameter = 2.0f * st.scene->boundsRadius();
    const int dirSize = std::max(st.dirShadows.size, 1);
    setFloat(p, "dirNormalOffset", 2.0f * diameter / float(dirSize));
    setFloat(p, "dirDepthBias", 0.5f / float(dirSize));
    setFloat(p, "planeDepthBias", 0.05f);
    setIvec2(p, "luminaireTableSize", kLuminaireTableC, kLuminaireTableGamma);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, st.lightBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, st.dirMatrices.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, st.skyLightBuffer.id());
    st.lightShadows.bind(8);
    glBindTextureUnit(12, st.dirShadows.depth.id());
    glBindTextureUnit(13, st.luminaireTables.id());
    glBindTextureUnit(14, st.skyShadows.depth.id());
    glBindTextureUnit(17, st.dirShadows.depth.id());
    glBindSampler(17, st.rawDepth.id());
    if (st.glazing) {
        glBindTextureUnit(15, st.dirShadows.transmittance.id());
        glBindTextureUnit(16, st.skyShadows.transmittance.id());
    }
}

// The uniforms of sky.glsl: the scene's sky and the sun's disc as seen by pixels with no surface.
void setBackgroundUniforms(const Preview::State& st, const gl::Program& p, bool sunDisc) {
    int model = 0;
    float zenith = 0, ground = 0, normalisation = 1;
    V3f towardSun(0, 1, 0);
    CieSkyParameters cie{0, -1, 0, -1, 0};
    if (const auto& sky = st.daylight.sky) {
        model = sky->sky.model == SkyModelType::Uniform ? 1 : sky->sky.model == SkyModelType::CieOvercast ? 2
              : sky->sky.model == SkyModelType::CieGeneral ? 3 : 4;
        zenith = float(sky->zenithLuminance / kLumensPerWatt);
        ground = float(sky->groundLuminance / kLumensPerWatt);
        towardSun = toFloat(sky->towardSun);
        const SkyDistribution relative = sky->distribution();
        if (model == 3) cie = cieSkyParameters(sky->sky.cieType);
        if (model == 4) {
            const PerezSky& perez = *relative.perez();
            const PerezCoefficients& k = perez.coefficients();
            cie = {k.a, k.b, k.c, k.d, k.e};
            towardSun = toFloat(perez.modelTowardSun());
            if (perez.isUniform()) model = 1;
        }
        normalisation = float(relative.normalisation());
    }
    setInt(p, "skyModel", model);
    setFloat(p, "skyZenithRadiance", zenith);
    setFloat(p, "groundRadiance", ground);
    setVec3(p, "skyTowardSun", towardSun);
    glProgramUniform4f(p.id(), loc(p, "cieAbcd"), float(cie.a), float(cie.b), float(cie.c), float(cie.d));
    setFloat(p, "cieE", float(cie.e));
    setFloat(p, "cieNormalisation", normalisation);
    const auto& sun = st.daylight.sun;
    setVec3(p, "sunToward", sun ? toFloat(sun->towardSun) : V3f(0, 1, 0));
    setFloat(p, "sunCosHalfAngle", sun ? float(std::cos(sun->halfAngleRad)) : 2.0f);
    const Rgb disc = sun && sunDisc ? toFloat(sun->radiance()) : Rgb(0, 0, 0);
    glProgramUniform3f(p.id(), loc(p, "sunDiscRadiance"), disc.x, disc.y, disc.z);
}

void bindTextures(std::initializer_list<GLuint> textures) {
    GLuint unit = 0;
    for (GLuint t : textures) glBindTextureUnit(unit++, t);
}

// The split (split.frag), with the discontinuity buffer when findEdges (seen from `eye`).
void runSplit(Preview::State& st, bool twoPass, int sourceW, int sourceH, bool findEdges = false, V3f eye = {}) {
    const gl::Program& p = st.splitProgram;
    glUseProgram(p.id());
    setIvec2(p, "pattern", st.patternX, st.patternY);
    setIvec2(p, "subSize", st.subW, st.subH);
    setInt(p, "blockSize", st.block);
    setInt(p, "findEdges", findEdges ? 1 : 0);
    setVec3(p, "cameraPos", eye);
    bindTextures({st.g[0].id(), st.g[1].id()});
    if (!twoPass) {
        setInt(p, "mode", 0);
        setIvec2(p, "sourceSize", sourceW, sourceH);
        drawFullscreen(st.sFbo.id(), st.splitW(), st.splitH());
        return;
    }
    setInt(p, "mode", 1);
    setIvec2(p, "sourceSize", sourceW, sourceH);
    drawFullscreen(st.tFbo.id(), st.splitW(), st.splitH());
    setInt(p, "mode", 2);
    setIvec2(p, "sourceSize", st.splitW(), st.splitH());
    bindTextures({st.t[0].id(), st.t[1].id(), st.t[2].id()});
    drawFullscreen(st.sFbo.id(), st.splitW(), st.splitH());
}

// Gathers a split-layout texture into blurTemp, blurred horizontally over boxWidth pixels where
// its alpha's discontinuity bits allow (boxWidth 1: gathered only).
void runGatherBlur(Preview::State& st, GLuint splitTexture, int boxWidth) {
    const gl::Program& p = st.blurProgram;
    glUseProgram(p.id());
    setIvec2(p, "pattern", st.patternX, st.patternY);
    setIvec2(p, "subSize", st.subW, st.subH);
    setInt(p, "boxWidth", boxWidth);
    setInt(p, "boxFlip", int(st.dealSeed & 1));
    bindTextures({splitTexture});
    drawFullscreen(st.blurFbo.id(), st.targetW, st.targetH);
}

std::vector<float> readBackRgba(GLuint texture, int w, int h) {
    std::vector<float> rgba(size_t(w) * size_t(h) * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
    return rgba;
}

Image readBack(GLuint texture, int w, int h) {
    const std::vector<float> rgba = readBackRgba(texture, w, h);
    Image img(w, h);
    for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = Rgb(rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]);
    return img;
}

// Milliseconds per pass: glFinish before each reading (llvmpipe and GPUs both run
// asynchronously), so that the passes' times are honest and add up.
class PassClock {
public:
    void lap(double& slot) {
        glFinish();
        const auto now = Clock::now();
        slot = std::chrono::duration<double, std::milli>(now - mark_).count();
        mark_ = now;
    }
    double total() const { return std::chrono::duration<double, std::milli>(Clock::now() - start_).count(); }

private:
    Clock::time_point start_ = Clock::now(), mark_ = start_;
};

// Which passes a frame draws, and how: from the settings and what the lights' and VPLs' upload
// left (so decided after it).
struct FramePlan {
    bool interleaved = false;  // n x m sub-buffers (else one: the image itself)
    bool splitPass = false;    // the G-buffer split in a pass of its own (not fused into the shading)
    bool indirect = false;     // VPLs to shade
    // Lights dealt to the sub-buffers (area samples, many delta lights) and the sky's directions
    // are shaded with the VPLs (shade_vpl.frag), so they are split, gathered and blurred with them.
    bool interleavedLights = false, interleavedSky = false;
    bool throughPanes = false;  // the camera sees the scene through panes
    // The shading pass's output holds light (else the direct pass adds none of it).
    bool shadesSubBuffers() const { return indirect || interleavedLights || interleavedSky; }
};

FramePlan planFrame(const Preview::State& st, const PreviewSettings& s, bool whiteReceivers) {
    FramePlan plan;
    plan.interleaved = s.patternX * s.patternY > 1;
    plan.splitPass = plan.interleaved && s.split != SplitMode::Fused;
    plan.indirect = s.indirect && st.uploadedVplCount > 0;
    plan.interleavedLights = plan.interleaved && s.direct && st.interleavedCount > 0;
    plan.interleavedSky = plan.interleaved && s.direct && st.skyPerTile > 0;
    // White receivers read the surface behind a pane as it is (the illuminance layer).
    plan.throughPanes = st.glazing && !whiteReceivers;
    return plan;
}

// The camera of a frame: its view-projection with the pixel sample at (jitterX, jitterY), the
// depth range just holding the scene.
struct FrameView {
    Mat4 viewProj;
    V3f eye;
    float jitterX = 0.5f, jitterY = 0.5f;
};

FrameView frameView(const Preview::State& st, float jitterX, float jitterY) {
    const float radius = st.scene->boundsRadius();
    const float dist = (toFloat(st.camera.position) - st.scene->boundsCenter()).length();
    const float farZ = dist + radius * 1.01f;
    const float nearZ = std::max((dist - radius) * 0.9f, farZ * 1e-5f);
    return {viewProjection(st.camera, st.width, st.height, jitterX, jitterY, nearZ, farZ), toFloat(st.camera.position),
            jitterX, jitterY};
}

// The VPLs and lights dealt anew when they changed, with the shadow maps of those that moved.
void uploadVplsAndLights(Preview::State& st, const PreviewSettings& s) {
    if (st.vplsDirty) uploadVpls(st, s);
    if (st.lightsDirty) uploadLights(st, s);
    st.degradation.clear();
    for (const std::string* note : {&st.vplNote, &st.lightNote, &st.paneNote})
        if (!note->empty()) st.degradation += (st.degradation.empty() ? "" : "; ") + *note;
}

// The G-buffer of the opaque triangles, and what the camera sees through panes: the product of
// the transmittances of those in front of each pixel's surface (glazing.frag), which the direct
// pass multiplies everything by.
void drawGBuffer(Preview::State& st, const FrameView& view, const FramePlan& plan, bool whiteReceivers) {
    glBindFramebuffer(GL_FRAMEBUFFER, st.gFbo.id());
    glViewport(0, 0, st.width, st.height);
    const float zero[4] = {0, 0, 0, 0};
    const GLuint zeroBits[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(st.gFbo.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferuiv(st.gFbo.id(), GL_COLOR, 1, zeroBits);
    const float one = 1.0f;
    glClearNamedFramebufferfv(st.gFbo.id(), GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(st.gbufferProgram.id());
    glProgramUniformMatrix4fv(st.gbufferProgram.id(), loc(st.gbufferProgram, "viewProj"), 1, GL_FALSE,
                              view.viewProj.m.data());
    setVec3(st.gbufferProgram, "cameraPos", view.eye);
    setInt(st.gbufferProgram, "whiteReceivers", whiteReceivers ? 1 : 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, st.triangles.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, st.materials.id());
    glBindVertexArray(st.sceneVao.id());
    glDrawArrays(GL_TRIANGLES, 0, st.opaqueVertexCount);
    if (plan.throughPanes) {
        const float white[4] = {1, 1, 1, 1};
        glClearNamedFramebufferfv(st.viewTransmittanceFbo.id(), GL_COLOR, 0, white);
        glBindFramebuffer(GL_FRAMEBUFFER, st.viewTransmittanceFbo.id());
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquationSeparate(GL_FUNC_ADD, GL_MIN);
        glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ONE, GL_ONE);
        const gl::Program& g = st.glazingProgram;
        glUseProgram(g.id());
        glProgramUniformMatrix4fv(g.id(), loc(g, "viewProj"), 1, GL_FALSE, view.viewProj.m.data());
        setInt(g, "firstTriangle", st.opaqueVertexCount / 3);
        glDrawArrays(GL_TRIANGLES, st.opaqueVertexCount, st.vertexCount - st.opaqueVertexCount);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(st.emptyVao.id());
}

// The interleaved shading (shade_vpl.frag): a draw per sub-buffer with its own VPLs, and its
// share of the interleaved lights and sky directions, into the split layout (or, without
// interleaving, the image).
void shadeSubBuffers(Preview::State& st, const PreviewSettings& s, const FramePlan& plan, const V3f& eye) {
    const bool fused = plan.interleaved && !plan.splitPass;
    const gl::Program& p =
        shadeProgram(st, plan.interleavedLights, plan.interleavedSky, plan.interleaved && s.blur, fused);
    glUseProgram(p.id());
    setIvec2(p, "pattern", st.patternX, st.patternY);
    setIvec2(p, "subSize", st.subW, st.subH);
    setIvec2(p, "sourceSize", st.width, st.height);
    setVec3(p, "cameraPos", eye);
    setFloat(p, "maxG", std::min(geometricClampBound(*st.scene, s.clampDistance), 3.0e38f));
    setFloat(p, "texelAngle", 2.0f / float(std::max(s.vplShadowSize, 1)));
    setFloat(p, "shadowBias", 0.03f);
    setFloat(p, "vplShadowSlack", st.proxyCaster.slack);
    setInt(p, "cubesPerChunk", st.vplShadows.perArray());
    setInt(p, "firstInterleaved", st.firstInterleaved);
    setInt(p, "interleavedCount", st.interleavedCount);
    setLightUniforms(st, p);
    glBindTextureUnit(0, plan.splitPass ? st.s[0].id() : st.g[0].id());
    glBindTextureUnit(1, plan.splitPass ? st.s[1].id() : st.g[1].id());
    glBindTextureUnit(2, st.s[2].id());
    st.vplShadows.bind(4);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, st.vplBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, st.paneTriangles.id());
    glBindFramebuffer(GL_FRAMEBUFFER, plan.interleaved ? st.indirectSplitFbo.id() : st.indirectFbo.id());
    const int tileW = plan.interleaved ? st.subW : st.width, tileH = plan.interleaved ? st.subH : st.height;
    for (int k = 0; k < s.patternX * s.patternY; ++k) {
        const Preview::State::TileVpls t =
            plan.indirect && size_t(k) < st.tiles.size() ? st.tiles[size_t(k)] : Preview::State::TileVpls{};
        const int tx = k % st.patternX, ty = k / st.patternX;
        if (st.unrolledVpls > 0)
            glBindBufferRange(GL_UNIFORM_BUFFER, 0, st.tileVplBlocks.id(), t.blockOffset,
                              GLsizeiptr(size_t(st.unrolledVpls) * sizeof(GpuVpl)));
        if (plan.interleavedSky)
            glBindBufferRange(GL_UNIFORM_BUFFER, 2, st.tileSkyBlocks.id(), k * st.skyBlockStride,
                              GLsizeiptr(size_t(st.skyPerTile) * sizeof(GpuSkyLight)));
        if (plan.interleavedLights && st.areaPerTile > 0)
            glBindBufferRange(GL_UNIFORM_BUFFER, 1, st.tileAreaBlocks.id(), k * st.areaBlockStride,
                              GLsizeiptr(size_t(st.areaPerTile) * sizeof(GpuLight)));
        setIvec2(p, "tile", tx, ty);
        setInt(p, "vplFirst", t.first);
        setInt(p, "vplCount", t.count);
        glViewport(tx * tileW, ty * tileH, tileW, tileH);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
}

// The last pass (direct.frag), into `final`: the vertical half of the blur over what the shading
// pass gave, the direct light of the lights shaded in full (without interleaving, the sky's
// directions too), the background where no surface is seen, all through the panes.
void drawDirect(Preview::State& st, const PreviewSettings& s, const FramePlan& plan, const FrameView& view,
                bool whiteReceivers, bool sunDiscShown) {
    const int shadedHere = s.direct ? st.shadedHere : 0;
    const int skyHere = s.direct && !plan.interleaved ? st.skyLightCount : 0;
    const gl::Program& d = directProgram(st, shadedHere > 0, skyHere > 0, s.direct && st.lightBlockSize > 0);
    glUseProgram(d.id());
    setBlockUniforms(st, d);
    setInt(d, "shadedHere", shadedHere);
    setInt(d, "skyLightCount", skyHere);
    setVec3(d, "cameraPos", view.eye);
    setLightUniforms(st, d);
    setInt(d, "addIndirect", plan.shadesSubBuffers() ? 1 : 0);
    setInt(d, "boxHeight", plan.interleaved && s.blur ? st.patternY : 1);
    setInt(d, "boxFlip", int(st.dealSeed & 1));
    {
        // The pinhole's rays for the background (SPEC.md section 1's camera).
        const V3d f = (st.camera.target - st.camera.position).normalized();
        const V3d r = f.cross(st.camera.up).normalized(), u = r.cross(f);
        const double t = std::tan(radians(st.camera.fovYDeg) * 0.5);
        setVec3(d, "viewForward", toFloat(f));
        setVec3(d, "viewRight", toFloat(r * (t * double(st.width) / double(st.height))));
        setVec3(d, "viewUp", toFloat(u * t));
        glProgramUniform2f(d.id(), loc(d, "viewJitter"), view.jitterX, view.jitterY);
    }
    setInt(d, "showBackground", whiteReceivers ? 0 : 1);
    setBackgroundUniforms(st, d, sunDiscShown);
    setInt(d, "throughPanes", plan.throughPanes ? 1 : 0);
    glBindTextureUnit(4, st.viewTransmittance.id());
    glBindTextureUnit(0, st.g[0].id());
    glBindTextureUnit(1, st.g[1].id());
    glBindTextureUnit(3, plan.interleaved ? st.blurTemp.id() : st.indirect.id());
    drawFullscreen(st.finalFbo.id(), st.width, st.height);
}

// The albedo of the surface under each pixel from the G-buffer, as channels albedo.R/G/B
// (diffuse and glossy surfaces; 0 on emitters, mirrors, glass and the background), so that
// illuminance can be read off the preview as off the converged image (render/display/display.h:
// E = pi L / albedo).
void readBackAlbedo(const Preview::State& st, Image& image) {
    const int w = st.width, h = st.height;
    const std::vector<float> g0 = readBackRgba(st.g[0].id(), w, h);
    std::vector<GLuint> g1(size_t(w) * size_t(h) * 4);
    glGetTextureImage(st.g[1].id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, GLsizei(g1.size() * sizeof(GLuint)), g1.data());
    for (int c = 0; c < 3; ++c) {
        std::vector<float>& layer = image.channels[std::string("albedo.") + "RGB"[c]];
        layer.resize(image.pixelCount());
        // gbuffer.glsl: kind 1 (floor of g0.w), albedo r, g in g1.y and b in g1.z's low half.
        for (size_t i = 0; i < layer.size(); ++i) {
            const GLuint word = g1[i * 4 + (c < 2 ? 1 : 2)];
            const GLuint bits = c == 1 ? word >> 16 : word & 0xffffu;
            layer[i] = int(g0[i * 4 + 3]) == 1 ? float(bits) / 65535.0f : 0.0f;
        }
    }
}

}  // namespace

Image Preview::render(float jitterX, float jitterY) {
    State& st = *state_;
    if (!st.scene) throw std::logic_error("preview: render() before setScene()");
    EglContext::ScopedCurrent current(*context_);
    PassClock clock;
    PreviewTimings& tm = st.timings;
    tm = PreviewTimings();
    const PreviewSettings& s = settings_;
    ensureTargets(st, st.width, st.height, s.patternX, s.patternY, s.split == SplitMode::TwoPass ? s.splitBlock : 1);
    uploadVplsAndLights(st, s);
    clock.lap(tm.shadows);

    const FramePlan plan = planFrame(st, s, whiteReceivers_);
    const FrameView view = frameView(st, jitterX, jitterY);
    drawGBuffer(st, view, plan, whiteReceivers_);
    clock.lap(tm.gbuffer);
    st.lightBlockSize = 0;
    if (st.interleavedDeltas && s.direct) chooseLightsPerBlock(st);
    clock.lap(tm.lightBlocks);

    if (plan.shadesSubBuffers()) {
        if (plan.splitPass) runSplit(st, s.split == SplitMode::TwoPass, st.width, st.height, s.blur, view.eye);
        clock.lap(tm.split);
        shadeSubBuffers(st, s, plan, view.eye);
        clock.lap(tm.shading);
        // Gathered and blurred horizontally; without interleaving the shading pass wrote the
        // image layout already, and there is no blur.
        if (plan.interleaved) runGatherBlur(st, st.indirectSplit.id(), s.blur ? st.patternX : 1);
        clock.lap(tm.gather);
    }

    drawDirect(st, s, plan, view, whiteReceivers_, sunDiscShown_);
    clock.lap(tm.direct);

    Image image = readBack(st.final.id(), st.width, st.height);
    if (albedoLayer_) readBackAlbedo(st, image);
    gl::checkErrors("Preview::render");
    clock.lap(tm.readback);
    tm.total = clock.total();
    image.attributes["lucerna:backend"] = "preview";
    return image;
}

Preview::SplitCheck Preview::splitAndGather(const Image& in) {
    State& st = *state_;
    EglContext::ScopedCurrent current(*context_);
    const PreviewSettings& s = settings_;
    ensureTargets(st, in.width, in.height, s.patternX, s.patternY, s.split == SplitMode::TwoPass ? s.splitBlock : 1);
    std::vector<float> rgba(in.pixels.size() * 4);
    for (size_t i = 0; i < in.pixels.size(); ++i) {
        rgba[i * 4] = in.pixels[i].x;
        rgba[i * 4 + 1] = in.pixels[i].y;
        rgba[i * 4 + 2] = in.pixels[i].z;
        rgba[i * 4 + 3] = float(i);
    }
    glTextureSubImage2D(st.g[0].id(), 0, 0, 0, in.width, in.height, GL_RGBA, GL_FLOAT, rgba.data());
    glBindVertexArray(st.emptyVao.id());
    runSplit(st, s.split == SplitMode::TwoPass, in.width, in.height);
    SplitCheck out;
    out.split = readBack(st.s[0].id(), st.splitW(), st.splitH());
    runGatherBlur(st, st.s[0].id(), 1);
    out.gathered = readBack(st.blurTemp.id(), in.width, in.height);
    out.subWidth = st.subW;
    out.subHeight = st.subH;
    gl::checkErrors("Preview::splitAndGather");
    return out;
}

}  // namespace lucerna
