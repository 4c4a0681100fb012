// The passes of one preview frame: shadow maps (only when lights or VPLs changed), G-buffer,
// split (with the discontinuity buffer), interleaved VPL shading, gather with the horizontal
// blur, vertical blur with the direct light and the blend.

#include "render/preview/gpu_state.h"
#include "render/preview/luminaire_textures.h"
#include "render/trace/rng.h"
#include "render/vpl/vpl_contribution.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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
    st.finalFbo = gl::makeFramebuffer({st.final.id()});
    gl::checkErrors("preview targets");
}

// Draws the six cube faces of every centre whose cube does not hold it already (CubeShadows::
// drawn), all in one instanced draw (the geometry shader picks layers): when one light of many
// changes, only its maps are drawn again.
void renderCubeShadows(Preview::State& st, CubeShadows& target, const std::vector<std::array<float, 4>>& centres,
                       int faceSize) {
    if (centres.empty()) return;
    GLint maxLayers = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    if (int(centres.size()) * 6 > maxLayers)
        throw std::runtime_error("preview: at most " + std::to_string(maxLayers / 6) +
                                 " shadow-mapped lights or VPLs on this GPU");
    target.ensure(faceSize, int(centres.size()));
    std::vector<std::array<float, 4>> stale;
    for (const auto& c : centres) {
        const auto cube = size_t(c[3]);
        if (cube >= target.drawn.size() || target.drawn[cube] != c) stale.push_back(c);
    }
    if (stale.empty()) return;
    upload(st.shadowCentres, stale);
    const float radius = st.scene->boundsRadius();
    const auto faces = cubeFaceMatrices(radius * 1e-3f, radius * 4.0f);
    glProgramUniformMatrix4fv(st.shadowProgram.id(), loc(st.shadowProgram, "faceProj"), 6, GL_FALSE,
                              faces[0].m.data());
    glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
    glViewport(0, 0, faceSize, faceSize);
    const float far = 1e30f, one = 1.0f;
    for (const auto& c : stale) {  // the stale cubes' six faces only
        const GLint firstLayer = GLint(c[3]) * 6;
        glClearTexSubImage(target.distance.id(), 0, 0, 0, firstLayer, faceSize, faceSize, 6, GL_RED, GL_FLOAT, &far);
        glClearTexSubImage(target.depth.id(), 0, 0, 0, firstLayer, faceSize, faceSize, 6, GL_DEPTH_COMPONENT, GL_FLOAT,
                           &one);
    }
    glEnable(GL_DEPTH_TEST);
    glUseProgram(st.shadowProgram.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, st.shadowCentres.id());
    glBindVertexArray(st.sceneVao.id());
    glDrawArraysInstanced(GL_TRIANGLES, 0, st.vertexCount, GLsizei(stale.size()));
    glDisable(GL_DEPTH_TEST);
    st.timings.shadowCubes += int(stale.size());
    for (const auto& c : stale) {
        const auto cube = size_t(c[3]);
        if (target.drawn.size() <= cube) target.drawn.resize(cube + 1, {0, 0, 0, -1});
        target.drawn[cube] = c;
    }
}

// An orthographic view-projection along a directional light's travel direction, over the scene's
// bounding sphere: clip x, y, z = the point's offsets along (side, up, direction) / radius.
Mat4 directionalShadowMatrix(const V3f& direction, const V3f& centre, float radius) {
    const V3f f = direction.normalized();
    const V3f helper = std::abs(f.y) < 0.9f ? V3f(0, 1, 0) : V3f(1, 0, 0);
    const V3f side = f.cross(helper).normalized(), up = side.cross(f);
    Mat4 m;
    const float k = 1.0f / (radius * 1.01f);
    m.setRow(0, side * k, -side.dot(centre) * k);
    m.setRow(1, up * k, -up.dot(centre) * k);
    m.setRow(2, f * k, -f.dot(centre) * k);
    m.setRow(3, V3f(0, 0, 0), 1.0f);
    return m;
}

// One depth-only draw of the scene per directional light (at most kMaxLights have maps).
void renderDirectionalShadows(Preview::State& st, int mapSize) {
    DirectionalShadows& ds = st.dirShadows;
    ds.ensure(mapSize, int(ds.matrices.size()));
    if (ds.matrices.empty()) return;
    glUseProgram(st.dirShadowProgram.id());
    glBindVertexArray(st.sceneVao.id());
    glEnable(GL_DEPTH_TEST);
    glViewport(0, 0, ds.size, ds.size);
    for (size_t i = 0; i < ds.matrices.size(); ++i) {
        glNamedFramebufferTextureLayer(ds.fbo.id(), GL_DEPTH_ATTACHMENT, ds.depth.id(), 0, GLint(i));
        glBindFramebuffer(GL_FRAMEBUFFER, ds.fbo.id());
        const float one = 1.0f;
        glClearNamedFramebufferfv(ds.fbo.id(), GL_DEPTH, 0, &one);
        glProgramUniformMatrix4fv(st.dirShadowProgram.id(), loc(st.dirShadowProgram, "lightViewProj"), 1, GL_FALSE,
                                  ds.matrices[i].m.data());
        glDrawArrays(GL_TRIANGLES, 0, st.vertexCount);
    }
    glDisable(GL_DEPTH_TEST);
}

// Bytes from one per-sub-buffer uniform block to the next: blockBytes rounded up to the offset
// alignment GL asks of glBindBufferRange.
size_t uniformBlockStride(size_t blockBytes) {
    GLint align = 1;
    glGetIntegerv(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT, &align);
    return size_t(roundUp(int(blockBytes), std::max(align, 1)));
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

// Interleaved, the area samples of each sub-buffer (sample i serves sub-buffer i mod (n m)) as
// uniform blocks, as uploadTileBlocks does for the VPLs: constant-index reads in shade_vpl.frag.
void uploadTileAreaBlocks(Preview::State& st, const std::vector<GpuLight>& lights) {
    constexpr int kMaxUnrolledArea = 16;
    const int subsets = st.patternX * st.patternY;
    const int perTile = subsets > 1 ? st.areaLightCount / subsets : 0;
    st.areaPerTile = perTile <= kMaxUnrolledArea ? perTile : 0;
    if (st.areaPerTile == 0) return;
    const size_t stride = uniformBlockStride(size_t(perTile) * sizeof(GpuLight));
    st.areaBlockStride = GLintptr(stride);
    std::vector<unsigned char> blocks(size_t(subsets) * stride);
    for (int k = 0; k < subsets; ++k)
        for (int j = 0; j < perTile; ++j)
            std::memcpy(blocks.data() + size_t(k) * stride + size_t(j) * sizeof(GpuLight),
                        &lights[size_t(st.firstAreaLight + k + j * subsets)], sizeof(GpuLight));
    upload(st.tileAreaBlocks, blocks);
}

// Orders the VPLs by sub-buffer: each light's set is shuffled and dealt round-robin, and a VPL's
// power is scaled by (set size / the set's VPLs in its sub-buffer) so that every sub-buffer alone
// estimates all the indirect light.
void uploadVpls(Preview::State& st, const PreviewSettings& settings) {
    const int subsets = st.patternX * st.patternY;
    std::vector<std::vector<std::pair<const Vpl*, float>>> buckets(static_cast<size_t>(subsets));
    Rng rng(st.seed, 0xde41ULL);
    int offset = 0;
    for (const LightVpls& set : st.sets) {
        std::vector<const Vpl*> order;
        for (const Vpl& v : set.vpls) order.push_back(&v);
        for (size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng.nextUint() % i]);
        std::vector<int> counts(size_t(subsets), 0);
        for (size_t j = 0; j < order.size(); ++j) ++counts[(j + size_t(offset)) % size_t(subsets)];
        for (size_t j = 0; j < order.size(); ++j) {
            const size_t k = (j + size_t(offset)) % size_t(subsets);
            buckets[k].push_back({order[j], float(order.size()) / float(counts[k])});
        }
        offset += int(order.size());
    }
    std::vector<GpuVpl> gpu;
    std::vector<std::array<float, 4>> centres;
    const float lift = st.scene->boundsRadius() * 1e-4f;
    st.tiles.clear();
    for (const auto& bucket : buckets) {
        st.tiles.push_back({int(gpu.size()), int(bucket.size()), 0});
        for (const auto& [v, scale] : bucket) {
            const ShadingMaterial& m = st.scene->material(v->material);
            GpuVpl g{};
            put(g.positionIndex, v->position, float(gpu.size()));
            put(g.normalAlpha, v->normal, m.alpha);
            // A diffuse VPL's BSDF is albedo / pi whatever the direction: premultiplied here.
            const bool glossy = m.type == MaterialType::Glossy && !isBlack(m.specular);
            put(g.incident, v->incident, glossy ? 1.0f : 0.0f);
            put(g.power, glossy ? v->power * scale : v->power * m.albedo * (scale / kPi), 0);
            put(g.albedo, m.albedo, 0);
            put(g.specular, m.type == MaterialType::Glossy ? m.specular : Rgb(0, 0, 0), 0);
            // The shadow map's centre sits just off the surface so the surface does not shadow it.
            const V3f c = v->position + v->normal * lift;
            centres.push_back({c.x, c.y, c.z, float(gpu.size())});
            gpu.push_back(g);
        }
    }
    upload(st.vplBuffer, gpu);
    uploadTileBlocks(st, gpu, settings.maxUnrolledVpls);
    st.uploadedVplCount = int(gpu.size());
    st.vplShadowChunks = 0;
    if (settings.visibility && !centres.empty()) {
        GLint maxLayers = 0;
        glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
        const int perChunk = std::max(1, int(maxLayers) / 6);
        const int chunks = (int(centres.size()) + perChunk - 1) / perChunk;
        if (chunks > Preview::State::kVplShadowChunks)
            throw std::runtime_error("preview: VPL visibility supports at most " +
                                     std::to_string(perChunk * Preview::State::kVplShadowChunks) + " VPLs on this GPU");
        st.vplCubesPerChunk = perChunk;
        st.vplShadowChunks = chunks;
        for (int c = 0; c < chunks; ++c) {
            const size_t first = size_t(c) * size_t(perChunk);
            const size_t last = std::min(centres.size(), first + size_t(perChunk));
            std::vector<std::array<float, 4>> part(centres.begin() + long(first), centres.begin() + long(last));
            for (auto& centre : part) centre[3] -= float(first);  // the cube's index inside its array
            renderCubeShadows(st, st.vplShadows[size_t(c)], part, settings.vplShadowSize);
        }
    }
    st.vplsDirty = false;
}

// Direct lights: the scene's delta lights, and point samples on the emissive triangles chosen in
// proportion to area times luminance, stratified, each lighting as Le / (samples pdf_area).
void uploadLights(Preview::State& st, const PreviewSettings& settings) {
    std::vector<GpuLight> lights;
    std::vector<std::array<float, 4>> centres;
    st.dirShadows.matrices.clear();
    st.firstAreaLight = st.areaLightCount = 0;
    const float toScene = 1.0f / (st.scene->metersPerUnit() * st.scene->metersPerUnit());
    std::vector<const GoniometricDistribution*> tables;
    GoniometricDistribution dark;  // for a luminaire whose file is not loaded
    dark.cAngles = {0, 360};
    dark.gammaAngles = {0, 180};
    dark.candela = {0, 0, 0, 0};
    for (const DeltaLight& d : st.deltas) {
        GpuLight g{};
        const float kind = d.type == LightType::Point       ? 0.0f
                           : d.type == LightType::Spot      ? 1.0f
                           : d.type == LightType::Luminaire ? 4.0f
                                                            : 2.0f;
        put(g.positionKind, d.position, kind);
        put(g.directionCosCone, d.direction, d.cosCone);
        if (d.type == LightType::Luminaire) {  // its table's layer in place of the cone
            put(g.directionCosCone, d.direction, float(tables.size()));
            tables.push_back(d.goniometric ? &d.goniometric->distribution() : &dark);
        }
        put(g.intensityCosFalloff, d.type == LightType::Directional ? d.intensity : d.intensity * toScene,
            d.cosFalloffStart);
        // Point and spot lights: a cube map; directional lights: an orthographic map (beyond
        // kMaxLights of them, unshadowed).
        float layer = -1.0f;
        if (d.type != LightType::Directional) {
            layer = float(centres.size());
            centres.push_back({d.position.x, d.position.y, d.position.z, layer});
        } else if (st.dirShadows.matrices.size() < size_t(DirectionalShadows::kMaxLights)) {
            layer = float(st.dirShadows.matrices.size());
            st.dirShadows.matrices.push_back(
                directionalShadowMatrix(d.direction, st.scene->boundsCenter(), st.scene->boundsRadius()));
        }
        // A luminaire keeps its C0 direction where area samples keep their normal.
        put(g.normalShadow, d.type == LightType::Luminaire ? d.c0 : V3f(0, 0, 0), layer);
        lights.push_back(g);
    }
    st.luminaireTables = makeLuminaireTables(tables);
    const auto& emitters = st.scene->lights().emitters();
    if (!emitters.empty() && settings.areaLightSamples > 0) {
        std::vector<double> cdf;
        double total = 0;
        for (const EmitterTriangle& e : emitters) cdf.push_back(total += e.area * std::max(1e-6f, luminance(e.radiance)));
        Rng rng(st.seed, 0xa4ea11ULL);
        // Interleaved: a multiple of the sub-buffer count, so every sub-buffer gets as many.
        const int subsets = st.patternX * st.patternY;
        const int n = subsets > 1 ? roundUp(settings.areaLightSamples, subsets) : settings.areaLightSamples;
        st.firstAreaLight = int(lights.size());
        st.areaLightCount = n;
        const float lift = st.scene->boundsRadius() * 1e-4f;
        for (int i = 0; i < n; ++i) {
            const double u = (i + rng.nextDouble()) / n;  // stratified over the emitters' power
            const size_t k = std::min(size_t(std::lower_bound(cdf.begin(), cdf.end(), u * total) - cdf.begin()),
                                      emitters.size() - 1);
            const EmitterTriangle& e = emitters[k];
            float b1 = rng.next1D(), b2 = rng.next1D();
            if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
            const V3f p = e.p0 * (1.0f - b1 - b2) + e.p1 * b1 + e.p2 * b2;
            const double weight = e.area * std::max(1e-6f, luminance(e.radiance));
            const float pdfArea = float(weight / total / e.area);
            GpuLight g{};
            put(g.positionKind, p, 3.0f);
            put(g.intensityCosFalloff, e.radiance * (1.0f / (float(n) * pdfArea)), 0);
            const float layer = float(centres.size());
            const V3f c = p + e.normal * lift;
            centres.push_back({c.x, c.y, c.z, layer});
            put(g.normalShadow, e.normal, layer);
            lights.push_back(g);
        }
        // Interleaved, sample i serves sub-buffer i mod (n m): shuffled, so that which part of the
        // light a sub-buffer sees changes with every seed (where the blur box is cut short by an
        // edge, a fixed assignment would be a bias that no number of frames averages away).
        for (size_t i = size_t(n); i > 1; --i)
            std::swap(lights[size_t(st.firstAreaLight) + i - 1], lights[size_t(st.firstAreaLight) + rng.nextUint() % i]);
    }
    upload(st.lightBuffer, lights);
    uploadTileAreaBlocks(st, lights);
    st.lightKinds = 0;
    for (const GpuLight& g : lights) st.lightKinds |= 1 << int(g.positionKind[3]);
    st.directLights = std::move(lights);
    renderCubeShadows(st, st.directShadows, centres, settings.shadowSize);
    renderDirectionalShadows(st, settings.shadowSize * 4);
    st.directShadowCubes = int(centres.size());
    st.lightsDirty = false;
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

// The VPL shading program for the current tiles, settings and scene (shade_vpl.frag's switches).
const gl::Program& shadeProgram(Preview::State& st, bool areaSamples, bool findEdges, bool fusedSplit) {
    std::string defines = define("VPL_SHADOW_CHUNKS", st.vplShadowChunks) + define("GLOSSY", st.glossyScene ? 1 : 0) +
                          define("AREA_SAMPLES", areaSamples ? 1 : 0) + define("FIND_EDGES", findEdges ? 1 : 0) +
                          define("FUSED_SPLIT", fusedSplit ? 1 : 0) + define("UNROLLED_AREA", areaSamples ? st.areaPerTile : 0) +
                          define("UNROLLED_VPLS", st.unrolledVpls) + "#define FOR_EACH_TILE_VPL(STEP)";
    for (int k = 0; k < st.unrolledVpls; ++k) defines += " STEP(" + std::to_string(k) + ")";
    return programVariant(st, "shade_vpl.frag", defines);
}

// The direct pass's program for the lights it evaluates (direct.frag's switches).
const gl::Program& directProgram(Preview::State& st, bool lightLoop) {
    const auto has = [&](int kind) { return (st.lightKinds >> kind) & 1; };
    return programVariant(st, "direct.frag",
                          define("LIGHT_LOOP", lightLoop ? 1 : 0) + define("SPOT", has(1)) + define("DIRECTIONAL", has(2)) +
                              define("AREA", has(3)) + define("LUMINAIRE", has(4)));
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
    glDrawArrays(GL_TRIANGLES, 0, st.vertexCount);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(st.emptyVao.id());
    lap(tm.gbuffer);

    const bool indirect = s.indirect && st.uploadedVplCount > 0;
    // Area lights, interleaved: their samples are shaded with the VPLs (shade_vpl.frag), so they
    // are split, gathered and blurred with them.
    const bool areaInterleaved = interleaved && s.direct && st.areaLightCount > 0;
    if (indirect || areaInterleaved) {
        const bool fused = interleaved && s.split == SplitMode::Fused;
        if (interleaved && !fused) runSplit(st, s.split == SplitMode::TwoPass, w, h, s.blur, eye);
        lap(tm.split);

        const gl::Program& p = shadeProgram(st, areaInterleaved, interleaved && s.blur, fused);
        glUseProgram(p.id());
        setIvec2(p, "pattern", st.patternX, st.patternY);
        setIvec2(p, "subSize", st.subW, st.subH);
        setIvec2(p, "sourceSize", w, h);
        setVec3(p, "cameraPos", eye);
        setFloat(p, "maxG", std::min(geometricClampBound(*st.scene, s.clampDistance), 3.0e38f));
        setFloat(p, "texelAngle", 2.0f / float(std::max(s.vplShadowSize, 1)));
        setFloat(p, "shadowBias", 0.03f);
        setInt(p, "firstArea", st.firstAreaLight);
        setInt(p, "areaCount", st.areaLightCount);
        setFloat(p, "areaShadowBias", 0.02f);
        setInt(p, "cubesPerChunk", st.vplCubesPerChunk);
        const bool splitLayout = interleaved && !fused;
        glBindTextureUnit(0, splitLayout ? st.s[0].id() : st.g[0].id());
        glBindTextureUnit(1, splitLayout ? st.s[1].id() : st.g[1].id());
        glBindTextureUnit(2, st.s[2].id());
        glBindTextureUnit(4, st.vplShadows[0].distance.id());
        glBindTextureUnit(5, st.directShadows.distance.id());
        for (int c = 1; c < Preview::State::kVplShadowChunks; ++c)
            glBindTextureUnit(GLuint(5 + c), st.vplShadows[size_t(c)].distance.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, st.vplBuffer.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, st.lightBuffer.id());
        glBindFramebuffer(GL_FRAMEBUFFER, interleaved ? st.indirectSplitFbo.id() : st.indirectFbo.id());
        const int tileW = interleaved ? st.subW : w, tileH = interleaved ? st.subH : h;
        for (int k = 0; k < subsets; ++k) {
            const Preview::State::TileVpls t =
                indirect && size_t(k) < st.tiles.size() ? st.tiles[size_t(k)] : Preview::State::TileVpls{};
            const int tx = k % st.patternX, ty = k / st.patternX;
            if (st.unrolledVpls > 0)
                glBindBufferRange(GL_UNIFORM_BUFFER, 0, st.tileVplBlocks.id(), t.blockOffset,
                                  GLsizeiptr(size_t(st.unrolledVpls) * sizeof(GpuVpl)));
            if (areaInterleaved && st.areaPerTile > 0)
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
    const bool withIndirect = indirect || areaInterleaved;  // the shading pass's output holds light

    // Lights evaluated here: the delta lights, and the area samples unless the VPL pass had them.
    const int directLightCount = !s.direct ? 0 : areaInterleaved ? st.firstAreaLight : int(st.directLights.size());
    const gl::Program& d = directProgram(st, directLightCount > 0);
    glUseProgram(d.id());
    setInt(d, "lightCount", int(st.directLights.size()));
    setVec3(d, "cameraPos", eye);
    setFloat(d, "shadowBias", 0.02f);
    setFloat(d, "texelAngle", 2.0f / float(std::max(s.shadowSize, 1)));
    setInt(d, "addDirect", s.direct ? 1 : 0);
    setInt(d, "firstArea", st.firstAreaLight);
    {
        const DirectionalShadows& ds = st.dirShadows;
        if (!ds.matrices.empty())
            glProgramUniformMatrix4fv(d.id(), loc(d, "dirShadowMatrix"), GLsizei(ds.matrices.size()), GL_FALSE,
                                      ds.matrices[0].m.data());
        // Two texels of the map along the normal, half a texel of depth (the map spans 2 radii).
        setFloat(d, "dirNormalOffset", 2.0f * 2.0f * radius / float(std::max(ds.size, 1)));
        setFloat(d, "dirDepthBias", 0.5f / float(std::max(ds.size, 1)));
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, st.lightBuffer.id());

    setInt(d, "areaMode", areaInterleaved ? 1 : 0);
    setInt(d, "addIndirect", withIndirect ? 1 : 0);
    setInt(d, "boxHeight", interleaved && s.blur ? st.patternY : 1);
    glBindTextureUnit(0, st.g[0].id());
    glBindTextureUnit(1, st.g[1].id());
    glBindTextureUnit(4, interleaved ? st.blurTemp.id() : st.indirect.id());
    glBindTextureUnit(5, st.directShadows.distance.id());
    glBindTextureUnit(6, st.dirShadows.depth.id());
    glBindTextureUnit(7, st.luminaireTables.id());
    setIvec2(d, "luminaireTableSize", kLuminaireTableC, kLuminaireTableGamma);
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
