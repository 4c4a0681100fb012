// The passes of one preview frame: shadow maps (only when lights or VPLs changed), G-buffer,
// split (with the discontinuity buffer), interleaved VPL shading, gather with the horizontal
// blur, vertical blur with the direct light and the blend.

#include "core/daylight/sky_model.h"
#include "render/preview/gpu_state.h"
#include "render/preview/luminaire_textures.h"
#include "render/trace/rng.h"
#include "render/vpl/vpl_contribution.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <unordered_map>
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

// The sub-buffers' VPLs as uniform blocks, one after the other at the alignment GL asks for,
// each unrolledVpls long (the shader's block size): when no sub-buffer has more than
// maxUnrolled, shade_vpl.frag reads them at constant indices (its UNROLLED_VPLS).
void uploadTileBlocks(Preview::State& st, const std::vector<GpuVpl>& gpu, int maxUnrolled) {
    int most = 0;
    for (const auto& t : st.tiles) most = std::max(most, t.count);
    st.unrolledVpls = most <= maxUnrolled ? most : 0;
    if (st.unrolledVpls == 0) return;
    const size_t blockBytes = size_t(st.unrolledVpls) * sizeof(GpuVpl);
    const size_t stride = uniformBlockStride(blockBytes);
    std::vector<unsigned char> blocks(st.tiles.size() * stride + blockBytes);
    for (size_t k = 0; k < st.tiles.size(); ++k) {
        auto& t = st.tiles[k];
        t.blockOffset = GLintptr(k * stride);
        std::memcpy(blocks.data() + k * stride, gpu.data() + t.first, size_t(t.count) * sizeof(GpuVpl));
    }
    upload(st.tileVplBlocks, blocks);
}

// Orders the VPLs by sub-buffer: each light's set is shuffled and dealt round-robin, and a VPL's
// power is scaled by (set size / the set's VPLs in its sub-buffer) so that every sub-buffer alone
// estimates all the indirect light. Beyond the shadow cubes this GPU holds, each set keeps a
// uniformly chosen share of its VPLs (the same scale keeps the estimate unbiased).
void uploadVpls(Preview::State& st, const PreviewSettings& settings) {
    const int subsets = st.patternX * st.patternY;
    struct Dealt {
        const Vpl* vpl;
        float scale;
        int cube;  // its shadow cube: its place among the kept VPLs in set order
    };
    std::vector<std::vector<Dealt>> buckets(static_cast<size_t>(subsets));
    // Which VPLs are kept follows the VPLs' seed; how they are dealt follows the deal's, so that
    // a new deal (Preview::redeal) keeps every VPL and with it its shadow cube.
    Rng keepRng(st.seed, 0xde41ULL), dealRng(st.dealSeed, 0xdea1ULL);
    size_t total = 0;
    for (const LightVpls& set : st.sets) total += set.vpls.size();
    const size_t capacity = size_t(CubeShadowSet::capacity());
    // Room for each set's rounding up to one VPL.
    const double keep = settings.visibility && total > capacity
                            ? double(capacity - std::min(capacity - 1, st.sets.size())) / double(total)
                            : 1.0;
    int offset = 0;
    size_t kept = 0;
    std::vector<V3f> centres;  // by cube
    const float lift = st.scene->boundsRadius() * 1e-4f;
    for (const LightVpls& set : st.sets) {
        std::vector<const Vpl*> order;
        for (const Vpl& v : set.vpls) order.push_back(&v);
        const size_t setSize = order.size();
        if (keep < 1.0 && setSize > 0) {
            for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[keepRng.nextUint() % i]);
            order.resize(std::max<size_t>(1, size_t(double(setSize) * keep)));
            std::sort(order.begin(), order.end());  // set order again: the cubes' order
        }
        std::vector<std::pair<const Vpl*, int>> cubes;  // in set order, then dealt
        for (const Vpl* v : order) {
            cubes.push_back({v, int(centres.size())});
            centres.push_back(v->position + v->normal * lift);
        }
        for (size_t i = cubes.size(); i > 1; --i) std::swap(cubes[i - 1], cubes[dealRng.nextUint() % i]);
        std::vector<int> counts(size_t(subsets), 0);
        for (size_t j = 0; j < cubes.size(); ++j) ++counts[(j + size_t(offset)) % size_t(subsets)];
        for (size_t j = 0; j < cubes.size(); ++j) {
            const size_t k = (j + size_t(offset)) % size_t(subsets);
            buckets[k].push_back({cubes[j].first, float(setSize) / float(counts[k]), cubes[j].second});
        }
        offset += int(order.size());
        kept += order.size();
    }
    st.vplNote = kept < total ? "shadow maps for " + std::to_string(kept) + " of " + std::to_string(total) +
                                    " VPLs (this GPU's limit; a random subset, scaled up)"
                              : "";
    std::vector<GpuVpl> gpu;
    st.tiles.clear();
    for (const auto& bucket : buckets) {
        st.tiles.push_back({int(gpu.size()), int(bucket.size()), 0});
        for (const auto& [v, scale, cube] : bucket) {
            const ShadingMaterial& m = st.scene->material(v->material);
            GpuVpl g{};
            put(g.positionIndex, v->position, float(cube));  // w: its shadow cube
            put(g.normalAlpha, v->normal, m.alpha);
            // A diffuse VPL's BSDF is albedo / pi whatever the direction: premultiplied here.
            const bool glossy = m.type == MaterialType::Glossy && !isBlack(m.specular);
            put(g.incident, v->incident, glossy ? 1.0f : 0.0f);
            put(g.power, glossy ? v->power * scale : v->power * m.albedo * (scale / kPi), 0);
            put(g.albedo, m.albedo, 0);
            put(g.specular, m.type == MaterialType::Glossy ? m.specular : Rgb(0, 0, 0), 0);
            gpu.push_back(g);
        }
    }
    upload(st.vplBuffer, gpu);
    uploadTileBlocks(st, gpu, settings.maxUnrolledVpls);
    st.uploadedVplCount = int(gpu.size());
    st.vplVisibility = settings.visibility && !centres.empty();
    if (st.vplVisibility) {
        st.vplShadows.reserve(int(centres.size()), settings.vplShadowSize);
        st.timings.shadowCubes += st.vplShadows.draw(st.shadowProgram, st.proxyCaster, centres, 0,
                                                     st.scene->boundsRadius(), st.shadowCentres);
    }
    st.vplsDirty = false;
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
                          define("UNROLLED_VPLS", st.unrolledVpls) + "#define FOR_EACH_TILE_VPL(STEP)";
    for (int k = 0; k < st.unrolledVpls; ++k) defines += " STEP(" + std::to_string(k) + ")";
    return programVariant(st, "shade_vpl.frag", defines);
}

// The direct pass's program for the lights it evaluates (direct.frag's switches).
const gl::Program& directProgram(Preview::State& st, bool lightLoop, bool skyLoop) {
    return programVariant(st, "direct.frag",
                          define("LIGHT_LOOP", lightLoop ? 1 : 0) + define("SKY_LIGHTS", skyLoop ? 1 : 0) +
                              lightKindDefines(st, lightLoop ? st.shadedKinds : 0));
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
        model = sky->sky.model == SkyModelType::Uniform ? 1 : sky->sky.model == SkyModelType::CieOvercast ? 2 : 3;
        zenith = float(sky->zenithLuminance / kLumensPerWatt);
        ground = float(sky->groundLuminance / kLumensPerWatt);
        towardSun = toFloat(sky->towardSun);
        if (model == 3) {
            cie = cieSkyParameters(sky->sky.cieType);
            normalisation = float(SkyDistribution(sky->sky, sky->towardSun).normalisation());
        }
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

}  // namespace

Image Preview::render(float jitterX, float jitterY) {
    State& st = *state_;
    if (!st.scene) throw std::logic_error("preview: render() before setScene()");
    EglContext::ScopedCurrent current(*context_);
    const auto start = Clock::now();
    auto mark = start;
    const auto lap = [&](double& slot) {
        glFinish();  // honest per-pass times: llvmpipe and GPUs both run asynchronously
        const auto now = Clock::now();
        slot = std::chrono::duration<double, std::milli>(now - mark).count();
        mark = now;
    };
    PreviewTimings& tm = st.timings;
    tm = PreviewTimings();
    const PreviewSettings& s = settings_;
    const int w = st.width, h = st.height;
    const int subsets = s.patternX * s.patternY;
    const bool interleaved = subsets > 1;
    ensureTargets(st, w, h, s.patternX, s.patternY, s.split == SplitMode::TwoPass ? s.splitBlock : 1);
    if (st.vplsDirty) uploadVpls(st, s);
    if (st.lightsDirty) uploadLights(st, s);
    st.degradation = st.vplNote + (st.vplNote.empty() || st.lightNote.empty() ? "" : "; ") + st.lightNote;
    lap(tm.shadows);

    // G-buffer.
    const float radius = st.scene->boundsRadius();
    const float dist = (toFloat(st.camera.position) - st.scene->boundsCenter()).length();
    const float farZ = dist + radius * 1.01f;
    const float nearZ = std::max((dist - radius) * 0.9f, farZ * 1e-5f);
    const Mat4 vp = viewProjection(st.camera, w, h, jitterX, jitterY, nearZ, farZ);
    const V3f eye = toFloat(st.camera.position);
    glBindFramebuffer(GL_FRAMEBUFFER, st.gFbo.id());
    glViewport(0, 0, w, h);
    const float zero[4] = {0, 0, 0, 0};
    const GLuint zeroBits[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(st.gFbo.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferuiv(st.gFbo.id(), GL_COLOR, 1, zeroBits);
    const float one = 1.0f;
    glClearNamedFramebufferfv(st.gFbo.id(), GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(st.gbufferProgram.id());
    glProgramUniformMatrix4fv(st.gbufferProgram.id(), loc(st.gbufferProgram, "viewProj"), 1, GL_FALSE, vp.m.data());
    setVec3(st.gbufferProgram, "cameraPos", eye);
    setInt(st.gbufferProgram, "whiteReceivers", whiteReceivers_ ? 1 : 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, st.triangles.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, st.materials.id());
    glBindVertexArray(st.sceneVao.id());
    glDrawArrays(GL_TRIANGLES, 0, st.opaqueVertexCount);
    // What the camera sees through panes: the product of the transmittances of those in front of
    // each pixel's surface (glazing.frag), which the direct pass multiplies everything by. White
    // receivers read the surface behind a pane as it is (the illuminance layer).
    const bool throughPanes = st.glazing && !whiteReceivers_;
    if (throughPanes) {
        const float white[4] = {1, 1, 1, 1};
        glClearNamedFramebufferfv(st.viewTransmittanceFbo.id(), GL_COLOR, 0, white);
        glBindFramebuffer(GL_FRAMEBUFFER, st.viewTransmittanceFbo.id());
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquationSeparate(GL_FUNC_ADD, GL_MIN);
        glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ONE, GL_ONE);
        const gl::Program& g = st.glazingProgram;
        glUseProgram(g.id());
        glProgramUniformMatrix4fv(g.id(), loc(g, "viewProj"), 1, GL_FALSE, vp.m.data());
        setInt(g, "firstTriangle", st.opaqueVertexCount / 3);
        glDrawArrays(GL_TRIANGLES, st.opaqueVertexCount, st.vertexCount - st.opaqueVertexCount);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(st.emptyVao.id());
    lap(tm.gbuffer);

    const bool indirect = s.indirect && st.uploadedVplCount > 0;
    // Lights dealt to the sub-buffers (area samples, many delta lights) are shaded with the VPLs
    // (shade_vpl.frag), so they are split, gathered and blurred with them.
    const bool interleavedLights = interleaved && s.direct && st.interleavedCount > 0;
    const bool interleavedSky = interleaved && s.direct && st.skyPerTile > 0;
    if (indirect || interleavedLights || interleavedSky) {
        const bool fused = interleaved && s.split == SplitMode::Fused;
        if (interleaved && !fused) runSplit(st, s.split == SplitMode::TwoPass, w, h, s.blur, eye);
        lap(tm.split);

        const gl::Program& p = shadeProgram(st, interleavedLights, interleavedSky, interleaved && s.blur, fused);
        glUseProgram(p.id());
        setIvec2(p, "pattern", st.patternX, st.patternY);
        setIvec2(p, "subSize", st.subW, st.subH);
        setIvec2(p, "sourceSize", w, h);
        setVec3(p, "cameraPos", eye);
        setFloat(p, "maxG", std::min(geometricClampBound(*st.scene, s.clampDistance), 3.0e38f));
        setFloat(p, "texelAngle", 2.0f / float(std::max(s.vplShadowSize, 1)));
        setFloat(p, "shadowBias", 0.03f);
        setFloat(p, "vplShadowSlack", st.proxyCaster.slack);
        setInt(p, "cubesPerChunk", st.vplShadows.perArray());
        setInt(p, "firstInterleaved", st.firstInterleaved);
        setInt(p, "interleavedCount", st.interleavedCount);
        setLightUniforms(st, p);
        const bool splitLayout = interleaved && !fused;
        glBindTextureUnit(0, splitLayout ? st.s[0].id() : st.g[0].id());
        glBindTextureUnit(1, splitLayout ? st.s[1].id() : st.g[1].id());
        glBindTextureUnit(2, st.s[2].id());
        st.vplShadows.bind(4);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, st.vplBuffer.id());
        glBindFramebuffer(GL_FRAMEBUFFER, interleaved ? st.indirectSplitFbo.id() : st.indirectFbo.id());
        const int tileW = interleaved ? st.subW : w, tileH = interleaved ? st.subH : h;
        for (int k = 0; k < subsets; ++k) {
            const Preview::State::TileVpls t =
                indirect && size_t(k) < st.tiles.size() ? st.tiles[size_t(k)] : Preview::State::TileVpls{};
            const int tx = k % st.patternX, ty = k / st.patternX;
            if (st.unrolledVpls > 0)
                glBindBufferRange(GL_UNIFORM_BUFFER, 0, st.tileVplBlocks.id(), t.blockOffset,
                                  GLsizeiptr(size_t(st.unrolledVpls) * sizeof(GpuVpl)));
            if (interleavedSky)
                glBindBufferRange(GL_UNIFORM_BUFFER, 2, st.tileSkyBlocks.id(), k * st.skyBlockStride,
                                  GLsizeiptr(size_t(st.skyPerTile) * sizeof(GpuSkyLight)));
            if (interleavedLights && st.areaPerTile > 0)
                glBindBufferRange(GL_UNIFORM_BUFFER, 1, st.tileAreaBlocks.id(), k * st.areaBlockStride,
                                  GLsizeiptr(size_t(st.areaPerTile) * sizeof(GpuLight)));
            setIvec2(p, "tile", tx, ty);
            setInt(p, "vplFirst", t.first);
            setInt(p, "vplCount", t.count);
            glViewport(tx * tileW, ty * tileH, tileW, tileH);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        lap(tm.shading);

        // Gathered and blurred horizontally; without interleaving the shading pass wrote the
        // image layout already, and there is no blur.
        if (interleaved) runGatherBlur(st, st.indirectSplit.id(), s.blur ? st.patternX : 1);
        lap(tm.gather);
    }
    // The shading pass's output holds light.
    const bool withIndirect = indirect || interleavedLights || interleavedSky;

    const int shadedHere = s.direct ? st.shadedHere : 0;
    // Without interleaving the sky's directions are all shaded here.
    const int skyHere = s.direct && !interleaved ? st.skyLightCount : 0;
    const gl::Program& d = directProgram(st, shadedHere > 0, skyHere > 0);
    glUseProgram(d.id());
    setInt(d, "shadedHere", shadedHere);
    setInt(d, "skyLightCount", skyHere);
    setVec3(d, "cameraPos", eye);
    setLightUniforms(st, d);
    setInt(d, "addIndirect", withIndirect ? 1 : 0);
    setInt(d, "boxHeight", interleaved && s.blur ? st.patternY : 1);
    setInt(d, "boxFlip", int(st.dealSeed & 1));
    {
        // The pinhole's rays for the background (SPEC.md section 1's camera).
        const V3d f = (st.camera.target - st.camera.position).normalized();
        const V3d r = f.cross(st.camera.up).normalized(), u = r.cross(f);
        const double t = std::tan(radians(st.camera.fovYDeg) * 0.5);
        setVec3(d, "viewForward", toFloat(f));
        setVec3(d, "viewRight", toFloat(r * (t * double(w) / double(h))));
        setVec3(d, "viewUp", toFloat(u * t));
        glProgramUniform2f(d.id(), loc(d, "viewJitter"), jitterX, jitterY);
    }
    setInt(d, "showBackground", whiteReceivers_ ? 0 : 1);
    setBackgroundUniforms(st, d, sunDiscShown_);
    setInt(d, "throughPanes", throughPanes ? 1 : 0);
    glBindTextureUnit(4, st.viewTransmittance.id());
    glBindTextureUnit(0, st.g[0].id());
    glBindTextureUnit(1, st.g[1].id());
    glBindTextureUnit(3, interleaved ? st.blurTemp.id() : st.indirect.id());
    drawFullscreen(st.finalFbo.id(), w, h);
    lap(tm.direct);

    Image image = readBack(st.final.id(), w, h);
    // The albedo layer from the G-buffer (diffuse and glossy surfaces; 0 on emitters, mirrors,
    // glass and the background), so that illuminance can be read off the preview as off the
    // converged image (render/display/display.h: E = pi L / albedo).
    if (albedoLayer_) {
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
    gl::checkErrors("Preview::render");
    lap(tm.readback);
    tm.total = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
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
