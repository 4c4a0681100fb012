// The preview's direct lights (gpu_state.h's ranges, lights.glsl's layout): the scene's delta
// lights, the emitters' point samples, and daylight (render/preview/daylight_samples.h: the sun
// shaded in full, the sky's directions dealt to the sub-buffers like the area samples), with
// their shadow maps.

#include "render/preview/daylight_samples.h"
#include "render/preview/gpu_state.h"
#include "render/preview/light_blocks.h"
#include "render/preview/luminaire_textures.h"
#include "render/trace/lights/tree_selection.h"
#include "render/trace/rng.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <unordered_map>

namespace lucerna::preview_detail {

namespace {

// Interleaved, the area samples of each sub-buffer (sample i serves sub-buffer i mod (n m)) as
// uniform blocks, as uploadTileBlocks does for the VPLs: constant-index reads in shade_vpl.frag.
void uploadTileAreaBlocks(Preview::State& st, const std::vector<GpuLight>& lights) {
    constexpr int kMaxUnrolledArea = 16;
    const int subsets = st.patternX * st.patternY;
    // Only when the dealt lights are area samples alone (areaSampleLight's cosine emitter).
    const int perTile = subsets > 1 && !st.interleavedDeltas ? st.areaLightCount / subsets : 0;
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

// A delta light for the light buffer (lights.glsl's layout), without its shadow layer; a
// luminaire's table goes into `tables` once however many luminaires share it (`layerOf`: the
// layer of each table there), so that a field of 10,000 luminaires of one file is one layer
// (the GPU's array textures hold 2,048 at least, not 10,000).
GpuLight gpuDeltaLight(const DeltaLight& d, float toScene, std::vector<const GoniometricDistribution*>& tables,
                       std::unordered_map<const GoniometricDistribution*, int>& layerOf) {
    static const GoniometricDistribution dark = [] {  // for a luminaire whose file is not loaded
        GoniometricDistribution g;
        g.cAngles = {0, 360};
        g.gammaAngles = {0, 180};
        g.candela = {0, 0, 0, 0};
        return g;
    }();
    GpuLight g{};
    const float kind = d.type == LightType::Point       ? 0.0f
                       : d.type == LightType::Spot      ? 1.0f
                       : d.type == LightType::Luminaire ? 4.0f
                                                        : 2.0f;
    put(g.positionKind, d.position, kind);
    put(g.directionCosCone, d.direction, d.cosCone);
    if (d.type == LightType::Luminaire) {  // its table's layer in place of the cone
        const GoniometricDistribution* table = d.goniometric ? &d.goniometric->distribution() : &dark;
        const auto [it, fresh] = layerOf.try_emplace(table, int(tables.size()));
        if (fresh) tables.push_back(table);
        put(g.directionCosCone, d.direction, float(it->second));
    }
    put(g.intensityCosFalloff, d.type == LightType::Directional ? d.intensity : d.intensity * toScene,
        d.cosFalloffStart);
    // A luminaire keeps its C0 direction where area samples keep their normal.
    put(g.normalShadow, d.type == LightType::Luminaire ? d.c0 : V3f(0, 0, 0), -1.0f);
    return g;
}

// Point samples on the emissive triangles chosen in proportion to area times luminance,
// stratified, each lighting as Le / (samples pdf_area); interleaved, a multiple of the sub-buffer
// count so that every sub-buffer gets as many, shuffled so that which part of the light a
// sub-buffer sees changes with every seed (where the blur box is cut short by an edge, a fixed
// assignment would be a bias that no number of frames averages away). Cost: a search in the
// emitters' CDF per sample, whatever their number.
std::vector<GpuLight> areaLightSamples(const RenderScene& scene, int count, uint64_t seed) {
    std::vector<GpuLight> samples;
    const auto& emitters = scene.lights().emitters();
    if (emitters.empty() || count <= 0) return samples;
    std::vector<double> cdf;
    double total = 0;
    for (const EmitterTriangle& e : emitters) cdf.push_back(total += e.area * std::max(1e-6f, luminance(e.radiance)));
    Rng rng(seed, 0xa4ea11ULL);
    for (int i = 0; i < count; ++i) {
        const double u = (i + rng.nextDouble()) / count;
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
        put(g.intensityCosFalloff, e.radiance * (1.0f / (float(count) * pdfArea)), 0);
        put(g.normalShadow, e.normal, -1.0f);
        samples.push_back(g);
    }
    for (size_t i = samples.size(); i > 1; --i) std::swap(samples[i - 1], samples[rng.nextUint() % i]);
    return samples;
}

// Delta lights dealt to each sub-buffer per frame at most (beyond, a random subset a frame): 16
// kept the VPL shading pass of a 135-light office near 80 ms at 640x480 on llvmpipe, where 62
// (1,000 lights) took 240 ms.
constexpr int kMaxInterleavedLights = 16;

// Bytes the delta lights' and area samples' cube maps may take (distance and depth, 8 bytes a
// texel): beyond, the faces shrink. 150 lights get 128 x 128 faces, 1,000 lights 32 x 32.
constexpr double kLightShadowBytes = 160.0 * 1024 * 1024;

// A directional light of the light buffer (kind 2: a scene's directional light or the sun) with
// its layer of the orthographic maps.
GpuLight directionalGpuLight(const DirectionalSample& d, int layer) {
    GpuLight g{};
    put(g.positionKind, V3f(0, 0, 0), 2.0f);
    put(g.directionCosCone, -d.toward, -1.0f);
    put(g.intensityCosFalloff, d.irradiance, 0.0f);
    put(g.normalShadow, V3f(0, 0, 0), float(layer));
    return g;
}

// The sky's directions for this fresh set (st.seed), a multiple of `multiple` of them (every
// sub-buffer gets as many), each with its map in st.skyShadows, dealt in the deal's order: sky
// light i lights sub-buffer i mod `multiple`. In st.skyLightBuffer, and with interleaving as one
// uniform block per sub-buffer in st.tileSkyBlocks (shade_vpl.frag's SKY_PER_TILE).
void uploadSkyLights(Preview::State& st, const PreviewSettings& settings, int multiple, Rng& deal) {
    std::vector<GpuSkyLight> sky;
    st.skyShadows.matrices.clear();
    if (st.daylight.sky && settings.skySamples > 0) {
        const int count = roundUp(settings.skySamples, multiple);
        for (const DirectionalSample& d : skySamples(*st.daylight.sky, count, hashSeed(st.seed, 0x5c7ULL))) {
            const Mat4 m = directionalShadowMatrix(-d.toward, st.scene->boundsCenter(), st.scene->boundsRadius());
            GpuSkyLight g{};
            put(g.towardLayer, d.toward, float(st.skyShadows.matrices.size()));
            put(g.irradiance, d.irradiance, 0.0f);
            std::copy(m.m.begin(), m.m.end(), g.shadow);
            sky.push_back(g);
            st.skyShadows.matrices.push_back(m);
        }
        for (size_t i = sky.size(); i > 1; --i) std::swap(sky[i - 1], sky[deal.nextUint() % i]);
    }
    st.skyLightCount = int(sky.size());
    upload(st.skyLightBuffer, sky);
    st.skyPerTile = multiple > 1 ? st.skyLightCount / multiple : 0;
    if (st.skyPerTile == 0) return;
    const size_t stride = uniformBlockStride(size_t(st.skyPerTile) * sizeof(GpuSkyLight));
    st.skyBlockStride = GLintptr(stride);
    std::vector<unsigned char> blocks(size_t(multiple) * stride);
    for (int k = 0; k < multiple; ++k)
        for (int j = 0; j < st.skyPerTile; ++j)
            std::memcpy(blocks.data() + size_t(k) * stride + size_t(j) * sizeof(GpuSkyLight),
                        &sky[size_t(k + j * multiple)], sizeof(GpuSkyLight));
    upload(st.tileSkyBlocks, blocks);
}

}  // namespace

// Direct lights: the scene's delta lights and the area lights' samples, in the ranges gpu_state.h
// describes, with their shadow maps: cube maps for point, spot and luminaire lights (the scene
// drawn) and area samples (the proxy drawn), orthographic maps for directional lights (beyond
// DirectionalShadows::kMaxLights, unshadowed). Past the cubes the GPU holds, the weakest delta
// lights go unshadowed; past the memory budget, every face shrinks; both are said in lightNote.
void uploadLights(Preview::State& st, const PreviewSettings& settings) {
    const int subsets = st.patternX * st.patternY;
    const bool interleave = subsets > 1;
    const float toScene = 1.0f / (st.scene->metersPerUnit() * st.scene->metersPerUnit());
    std::vector<const GoniometricDistribution*> tables;
    std::unordered_map<const GoniometricDistribution*, int> layerOf;
    std::vector<GpuLight> directional, deltas;
    std::vector<double> deltaPower;
    std::vector<LightBounds> deltaBounds;  // for the blocks' choice (no bounds: intensity 0, never chosen)
    st.dirShadows.matrices.clear();
    // The sun first, so that it always has a map; its direction is drawn within the disc anew for
    // each fresh set (st.seed), so that accumulated frames show the disc's penumbra.
    if (st.daylight.sun)
        if (const auto sun = sunSample(*st.daylight.sun, hashSeed(st.seed, 0x5a11ULL))) {
            directional.push_back(directionalGpuLight(*sun, 0));
            directional.back().normalShadow[0] = 1.0f;  // lights.glsl: looked up by the receiver's plane
            st.dirShadows.matrices.push_back(
                directionalShadowMatrix(-sun->toward, st.scene->boundsCenter(), st.scene->boundsRadius()));
        }
    for (const DeltaLight& d : st.deltas) {
        if (d.type == LightType::Sun) continue;  // the daylight's (above), not a delta light
        GpuLight g = gpuDeltaLight(d, toScene, tables, layerOf);
        if (d.type != LightType::Directional) {
            deltas.push_back(g);
            // Intensity over the cone's solid angle share: which lights matter most.
            deltaPower.push_back(double(luminance(d.intensity)) * (d.type == LightType::Spot ? 1.0 - d.cosCone : 2.0));
            const std::optional<LightBounds> bounds = deltaLightBounds(d, st.scene->metersPerUnit());
            deltaBounds.push_back(bounds ? *bounds : LightBounds());
            continue;
        }
        if (st.dirShadows.matrices.size() < size_t(DirectionalShadows::kMaxLights)) {
            g.normalShadow[3] = float(st.dirShadows.matrices.size());
            st.dirShadows.matrices.push_back(
                directionalShadowMatrix(d.direction, st.scene->boundsCenter(), st.scene->boundsRadius()));
        }
        directional.push_back(g);
    }
    st.luminaireTables = makeLuminaireTables(tables);
    const int areaCount = interleave ? roundUp(settings.areaLightSamples, subsets) : settings.areaLightSamples;
    std::vector<GpuLight> area = areaLightSamples(*st.scene, areaCount, st.seed);

    // Shadow cubes: the delta lights in scene order (so that an edit redraws one), then the area
    // samples; the strongest delta lights keep theirs when not all fit.
    const int capacity = CubeShadowSet::capacity();
    const int areaCubes = std::min(int(area.size()), capacity);
    const int shadowedDeltas = std::min(int(deltas.size()), capacity - areaCubes);
    std::vector<size_t> byPower(deltas.size());
    std::iota(byPower.begin(), byPower.end(), size_t(0));
    std::stable_sort(byPower.begin(), byPower.end(), [&](size_t a, size_t b) { return deltaPower[a] > deltaPower[b]; });
    std::vector<bool> shadowed(deltas.size(), false);
    for (int r = 0; r < shadowedDeltas; ++r) shadowed[byPower[size_t(r)]] = true;
    std::vector<V3f> deltaCentres, areaCentres;
    for (size_t i = 0; i < deltas.size(); ++i)
        if (shadowed[i]) {
            deltas[i].normalShadow[3] = float(deltaCentres.size());
            deltaCentres.push_back(V3f(deltas[i].positionKind[0], deltas[i].positionKind[1], deltas[i].positionKind[2]));
        }
    const float lift = st.scene->boundsRadius() * 1e-4f;
    for (int i = 0; i < areaCubes; ++i) {
        GpuLight& g = area[size_t(i)];
        g.normalShadow[3] = float(shadowedDeltas + i);
        areaCentres.push_back(V3f(g.positionKind[0], g.positionKind[1], g.positionKind[2]) +
                              V3f(g.normalShadow[0], g.normalShadow[1], g.normalShadow[2]) * lift);
    }
    const int cubes = shadowedDeltas + areaCubes;
    int face = settings.shadowSize;
    while (face > 16 && double(cubes) * 6.0 * face * face * 8.0 > kLightShadowBytes) face /= 2;
    st.lightNote.clear();
    if (shadowedDeltas < int(deltas.size()))
        st.lightNote = "shadows for the " + std::to_string(shadowedDeltas) + " strongest of " +
                       std::to_string(deltas.size()) + " lights (this GPU's limit)";
    if (face < settings.shadowSize)
        st.lightNote += std::string(st.lightNote.empty() ? "" : ", ") + "light shadow maps at " + std::to_string(face) +
                        " px a face for " + std::to_string(cubes) + " maps";

    // The ranges: shaded in full, then dealt to the sub-buffers (many delta lights, padded with
    // dark ones to a multiple of n m so that every sub-buffer gets as many; the area samples).
    Rng rng(st.dealSeed, 0xd1ea7ULL);
    // The area samples' deal follows the deal's seed; each keeps its cube (assigned above).
    for (size_t i = area.size(); i > 1; --i) std::swap(area[i - 1], area[rng.nextUint() % i]);
    // The sky's directions: many, and soft light, so dealt to the sub-buffers like the area
    // samples, in buffers of their own (a loop of their own: through the general light loop they
    // cost three times as much on llvmpipe).
    uploadSkyLights(st, settings, interleave ? subsets : 1, rng);
    std::vector<GpuLight> lights = directional;
    st.interleavedDeltas = interleave && int(deltas.size()) > settings.lightsShadedInFull;
    if (!st.interleavedDeltas) {
        lights.insert(lights.end(), deltas.begin(), deltas.end());
        if (!interleave) lights.insert(lights.end(), area.begin(), area.end());
    }
    st.shadedHere = int(lights.size());
    st.firstInterleaved = int(lights.size());
    // Dealt to the sub-buffers: every delta light (or, past kMaxInterleavedLights a sub-buffer, a
    // uniformly chosen subset scaled up, so that the cost per pixel stays that of
    // kMaxInterleavedLights lights and accumulated frames converge), padded with dark lights to a
    // multiple of n m. dealtAt: where each delta light went (light_blocks.glsl takes a block's own
    // lights' share back out).
    std::vector<int32_t> dealtAt(deltas.size(), -1);
    if (st.interleavedDeltas) {
        std::vector<int32_t> dealt(deltas.size());
        std::iota(dealt.begin(), dealt.end(), 0);
        float scale = 1.0f;
        const size_t most = size_t(kMaxInterleavedLights * subsets);
        if (dealt.size() > most) {
            for (size_t i = 0; i < most; ++i) std::swap(dealt[i], dealt[i + rng.nextUint() % (dealt.size() - i)]);
            scale = float(dealt.size()) / float(most);
            st.lightNote += std::string(st.lightNote.empty() ? "" : ", ") + "a random " + std::to_string(most) +
                            " of " + std::to_string(dealt.size()) + " lights dealt a frame";
            dealt.resize(most);
        }
        dealt.resize(size_t(roundUp(int(dealt.size()), subsets)), -1);
        for (size_t i = dealt.size(); i > 1; --i) std::swap(dealt[i - 1], dealt[rng.nextUint() % i]);
        GpuLight darkLight{};
        darkLight.normalShadow[3] = -1.0f;
        for (size_t i = 0; i < dealt.size(); ++i) {
            const int32_t j = dealt[i];
            GpuLight g = j >= 0 ? deltas[size_t(j)] : darkLight;
            for (int c = 0; c < 3; ++c) g.intensityCosFalloff[c] *= scale;
            lights.push_back(g);
            if (j >= 0) dealtAt[size_t(j)] = int32_t(i);
        }
    }
    st.firstAreaLight = int(lights.size());
    st.areaLightCount = interleave ? int(area.size()) : 0;
    if (interleave) lights.insert(lights.end(), area.begin(), area.end());
    st.interleavedCount = int(lights.size()) - st.firstInterleaved;
    upload(st.dealtAt, dealtAt);
    // Every delta light, for the blocks' choice (chooseLightsPerBlock, each frame).
    st.firstBlockLight = int(lights.size());
    if (st.interleavedDeltas) lights.insert(lights.end(), deltas.begin(), deltas.end());
    st.lightsPerBlock = st.interleavedDeltas ? settings.lightsShadedInFull : 0;
    st.deltaTree = st.interleavedDeltas ? LightTree(deltaBounds) : LightTree();
    // The blocks' grid moves with each deal, so that accumulated frames do not keep one block's
    // choice along a fixed line (reduced modulo the block size each frame).
    st.lightBlockOffsetX = int(rng.nextUint() % 1024u);
    st.lightBlockOffsetY = int(rng.nextUint() % 1024u);

    const auto kinds = [&](int first, int end) {
        int bits = 0;
        for (int i = first; i < end; ++i) bits |= 1 << int(lights[size_t(i)].positionKind[3]);
        return bits;
    };
    st.shadedKinds = kinds(0, st.shadedHere) | kinds(st.firstBlockLight, int(lights.size()));
    st.interleavedKinds = kinds(st.firstInterleaved, st.firstBlockLight);
    upload(st.lightBuffer, lights);
    uploadTileAreaBlocks(st, lights);
    st.directLights = std::move(lights);

    st.lightShadows.reserve(cubes, face);
    const float radius = st.scene->boundsRadius();
    st.timings.shadowCubes += st.lightShadows.draw(st.shadowProgram, st.sceneCaster, deltaCentres, 0, radius, st.shadowCentres);
    st.timings.shadowCubes +=
        st.lightShadows.draw(st.shadowProgram, st.proxyCaster, areaCentres, shadowedDeltas, radius, st.shadowCentres);
    // Orthographic maps, drawn again only where a direction changed (a new deal draws none): the
    // scene's directional lights and the sun, then the sky's; panes in their transmittance layers.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, st.triangles.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, st.materials.id());
    st.timings.directionalMaps +=
        st.dirShadows.draw(st.dirShadowProgram, st.sceneCaster, st.glazingShadowProgram, st.paneCaster,
                           settings.shadowSize * 4, st.glazing);
    st.timings.directionalMaps +=
        st.skyShadows.draw(st.dirShadowProgram, st.sceneCaster, st.glazingShadowProgram, st.paneCaster,
                           settings.skyShadowSize, st.glazing);
    upload(st.dirMatrices, st.dirShadows.matrices);
    st.lightsDirty = false;
}

// Blocks of 4 pixels, larger on large images so that there are at most about 2,400 of them: the
// choice costs a descent of the light tree per block on the CPU (13 ms for 1,000 lights at
// 640x480, BENCHMARKS.md). Smaller blocks hold fewer lamps' hot spots at one tie of the bound:
// on the hall of 1,000 lights at 160x120, 8-pixel blocks gained nothing, 4-pixel blocks 1.5x.
int lightBlockSize(int width, int height) {
    const double side = std::sqrt(double(width) * double(height) / 2400.0);
    return std::max(4, roundUp(int(std::ceil(side)), 4));
}

void chooseLightsPerBlock(Preview::State& st) {
    const int size = lightBlockSize(st.width, st.height);
    st.lightBlockSize = size;
    // One block more each way: the offset shifts the grid by up to a block.
    const int blocksX = (st.width + size - 1) / size + 1, blocksY = (st.height + size - 1) / size + 1;
    const int ox = st.lightBlockOffsetX % size, oy = st.lightBlockOffsetY % size;
    if (blocksX != st.lightBlocksX || blocksY != st.lightBlocksY) {  // the boxes' targets, a texel a block
        st.lightBlocksX = blocksX;
        st.lightBlocksY = blocksY;
        for (auto& t : st.blockBoxes) t = gl::makeTexture2D(GL_RGBA32F, blocksX, blocksY);
        st.blockBoxFbo = gl::makeFramebuffer({st.blockBoxes[0].id(), st.blockBoxes[1].id()});
    }
    const gl::Program& p = st.blockBoundsProgram;
    glUseProgram(p.id());
    setInt(p, "lightBlockSize", size);
    setIvec2(p, "lightBlockOffset", ox, oy);
    glBindTextureUnit(0, st.g[0].id());
    drawFullscreen(st.blockBoxFbo.id(), blocksX, blocksY);
    const size_t count = size_t(blocksX) * size_t(blocksY);
    std::vector<float> lo(count * 4), hi(count * 4);
    glGetTextureImage(st.blockBoxes[0].id(), 0, GL_RGBA, GL_FLOAT, GLsizei(lo.size() * sizeof(float)), lo.data());
    glGetTextureImage(st.blockBoxes[1].id(), 0, GL_RGBA, GL_FLOAT, GLsizei(hi.size() * sizeof(float)), hi.data());
    std::vector<BlockBounds> blocks(count);
    for (size_t b = 0; b < count; ++b) {
        blocks[b].empty = !(lo[b * 4 + 3] > 0);  // light_block_bounds.frag: the pixels seen in alpha
        blocks[b].lo = V3f(lo[b * 4], lo[b * 4 + 1], lo[b * 4 + 2]);
        blocks[b].hi = V3f(hi[b * 4], hi[b * 4 + 1], hi[b * 4 + 2]);
    }
    const std::vector<int32_t> chosen = chooseBlockLights(blocks, st.deltaTree, st.lightsPerBlock);
    upload(st.blockLights, chosen);
}

}  // namespace lucerna::preview_detail
