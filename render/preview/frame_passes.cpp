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
    st.finalFbo = gl::makeFramebuffer({st.final.id()});
    gl::checkErrors("preview targets");
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
    st.dirShadows.matrices.clear();
    for (const DeltaLight& d : st.deltas) {
        GpuLight g = gpuDeltaLight(d, toScene, tables, layerOf);
        if (d.type != LightType::Directional) {
            deltas.push_back(g);
            // Intensity over the cone's solid angle share: which lights matter most.
            deltaPower.push_back(double(luminance(d.intensity)) * (d.type == LightType::Spot ? 1.0 - d.cosCone : 2.0));
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
    std::vector<GpuLight> lights = directional;
    st.interleavedDeltas = interleave && int(deltas.size()) > settings.lightsShadedInFull;
    if (!st.interleavedDeltas) {
        lights.insert(lights.end(), deltas.begin(), deltas.end());
    } else {
        // The lights that matter most to the picture stay shaded in full: those nearest the
        // camera for their power, whose pools of light (and the hot spots where a lamp hangs
        // close to the ceiling) cover the most pixels; the blur would smear their shape.
        const V3f eye = toFloat(st.camera.position);
        const float nearest = 0.05f * st.scene->boundsRadius();
        std::vector<double> score(deltas.size());
        for (size_t i = 0; i < deltas.size(); ++i) {
            const V3f p(deltas[i].positionKind[0], deltas[i].positionKind[1], deltas[i].positionKind[2]);
            score[i] = deltaPower[i] / std::max(double((p - eye).length2()), double(nearest) * nearest);
        }
        std::vector<size_t> order(deltas.size());
        std::iota(order.begin(), order.end(), size_t(0));
        const size_t full = size_t(std::max(settings.lightsShadedInFull, 0));
        std::partial_sort(order.begin(), order.begin() + long(full), order.end(),
                          [&](size_t a, size_t b) { return score[a] > score[b]; });
        std::vector<GpuLight> rest;
        std::vector<bool> inFull(deltas.size(), false);
        for (size_t r = 0; r < full; ++r) inFull[order[r]] = true;
        for (size_t i = 0; i < deltas.size(); ++i) (inFull[i] ? lights : rest).push_back(deltas[i]);
        deltas = std::move(rest);
    }
    if (!interleave) lights.insert(lights.end(), area.begin(), area.end());
    st.shadedHere = int(lights.size());
    st.firstInterleaved = int(lights.size());
    if (st.interleavedDeltas && int(deltas.size()) > kMaxInterleavedLights * subsets) {
        // A frame shades a uniformly chosen subset of the rest, scaled up: the cost per pixel
        // stays that of kMaxInterleavedLights lights, and frames accumulated while idle converge.
        for (size_t i = 0; i < size_t(kMaxInterleavedLights * subsets); ++i)
            std::swap(deltas[i], deltas[i + rng.nextUint() % (deltas.size() - i)]);
        const float scale = float(deltas.size()) / float(kMaxInterleavedLights * subsets);
        st.lightNote += std::string(st.lightNote.empty() ? "" : ", ") + "a random " +
                        std::to_string(kMaxInterleavedLights * subsets) + " of " + std::to_string(deltas.size()) +
                        " far lights a frame";
        deltas.resize(size_t(kMaxInterleavedLights * subsets));
        for (GpuLight& g : deltas)
            for (int c = 0; c < 3; ++c) g.intensityCosFalloff[c] *= scale;
    }
    if (st.interleavedDeltas) {
        GpuLight darkLight{};
        darkLight.normalShadow[3] = -1.0f;
        deltas.resize(size_t(roundUp(int(deltas.size()), subsets)), darkLight);
        for (size_t i = deltas.size(); i > 1; --i) std::swap(deltas[i - 1], deltas[rng.nextUint() % i]);
        lights.insert(lights.end(), deltas.begin(), deltas.end());
    }
    st.firstAreaLight = int(lights.size());
    st.areaLightCount = interleave ? int(area.size()) : 0;
    if (interleave) lights.insert(lights.end(), area.begin(), area.end());
    st.interleavedCount = int(lights.size()) - st.firstInterleaved;

    const auto kinds = [&](int first, int end) {
        int bits = 0;
        for (int i = first; i < end; ++i) bits |= 1 << int(lights[size_t(i)].positionKind[3]);
        return bits;
    };
    st.shadedKinds = kinds(0, st.shadedHere);
    st.interleavedKinds = kinds(st.firstInterleaved, int(lights.size()));
    upload(st.lightBuffer, lights);
    uploadTileAreaBlocks(st, lights);
    st.directLights = std::move(lights);

    st.lightShadows.reserve(cubes, face);
    const float radius = st.scene->boundsRadius();
    st.timings.shadowCubes += st.lightShadows.draw(st.shadowProgram, st.sceneCaster, deltaCentres, 0, radius, st.shadowCentres);
    st.timings.shadowCubes +=
        st.lightShadows.draw(st.shadowProgram, st.proxyCaster, areaCentres, shadowedDeltas, radius, st.shadowCentres);
    st.dirShadows.draw(st.dirShadowProgram, st.sceneCaster, settings.shadowSize * 4);
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

std::string lightKindDefines(int kinds) {
    const auto has = [&](int kind) { return (kinds >> kind) & 1; };
    return define("SPOT", has(1)) + define("DIRECTIONAL", has(2)) + define("AREA", has(3)) + define("LUMINAIRE", has(4));
}

// The VPL shading program for the current tiles, settings and scene (shade_vpl.frag's switches).
const gl::Program& shadeProgram(Preview::State& st, bool interleavedLights, bool findEdges, bool fusedSplit) {
    std::string defines = define("VPL_VISIBILITY", st.vplVisibility ? 1 : 0) + define("GLOSSY", st.glossyScene ? 1 : 0) +
                          define("INTERLEAVED_LIGHTS", interleavedLights ? 1 : 0) + define("FIND_EDGES", findEdges ? 1 : 0) +
                          define("FUSED_SPLIT", fusedSplit ? 1 : 0) +
                          define("UNROLLED_AREA", interleavedLights ? st.areaPerTile : 0) +
                          lightKindDefines(interleavedLights ? st.interleavedKinds : 0) +
                          define("UNROLLED_VPLS", st.unrolledVpls) + "#define FOR_EACH_TILE_VPL(STEP)";
    for (int k = 0; k < st.unrolledVpls; ++k) defines += " STEP(" + std::to_string(k) + ")";
    return programVariant(st, "shade_vpl.frag", defines);
}

// The direct pass's program for the lights it evaluates (direct.frag's switches).
const gl::Program& directProgram(Preview::State& st, bool lightLoop) {
    return programVariant(st, "direct.frag",
                          define("LIGHT_LOOP", lightLoop ? 1 : 0) + lightKindDefines(lightLoop ? st.shadedKinds : 0));
}

// The uniforms and textures of lights.glsl.
void setLightUniforms(Preview::State& st, const gl::Program& p) {
    setFloat(p, "lightShadowBias", 0.02f);
    setFloat(p, "lightTexelAngle", 2.0f / float(std::max(st.lightShadows.faceSize(), 1)));
    setFloat(p, "areaShadowSlack", st.proxyCaster.slack);
    setInt(p, "lightCubesPerArray", st.lightShadows.perArray());
    const DirectionalShadows& ds = st.dirShadows;
    if (!ds.matrices.empty())
        glProgramUniformMatrix4fv(p.id(), loc(p, "dirShadowMatrix"), GLsizei(ds.matrices.size()), GL_FALSE,
                                  ds.matrices[0].m.data());
    // Two texels of the map along the normal, half a texel of depth (the map spans 2 radii).
    setFloat(p, "dirNormalOffset", 2.0f * 2.0f * st.scene->boundsRadius() / float(std::max(ds.size, 1)));
    setFloat(p, "dirDepthBias", 0.5f / float(std::max(ds.size, 1)));
    setIvec2(p, "luminaireTableSize", kLuminaireTableC, kLuminaireTableGamma);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, st.lightBuffer.id());
    st.lightShadows.bind(8);
    glBindTextureUnit(12, st.dirShadows.depth.id());
    glBindTextureUnit(13, st.luminaireTables.id());
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
    glDrawArrays(GL_TRIANGLES, 0, st.vertexCount);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(st.emptyVao.id());
    lap(tm.gbuffer);

    const bool indirect = s.indirect && st.uploadedVplCount > 0;
    // Lights dealt to the sub-buffers (area samples, many delta lights) are shaded with the VPLs
    // (shade_vpl.frag), so they are split, gathered and blurred with them.
    const bool interleavedLights = interleaved && s.direct && st.interleavedCount > 0;
    if (indirect || interleavedLights) {
        const bool fused = interleaved && s.split == SplitMode::Fused;
        if (interleaved && !fused) runSplit(st, s.split == SplitMode::TwoPass, w, h, s.blur, eye);
        lap(tm.split);

        const gl::Program& p = shadeProgram(st, interleavedLights, interleaved && s.blur, fused);
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
    const bool withIndirect = indirect || interleavedLights;  // the shading pass's output holds light

    const int shadedHere = s.direct ? st.shadedHere : 0;
    const gl::Program& d = directProgram(st, shadedHere > 0);
    glUseProgram(d.id());
    setInt(d, "shadedHere", shadedHere);
    setVec3(d, "cameraPos", eye);
    setLightUniforms(st, d);
    setInt(d, "addIndirect", withIndirect ? 1 : 0);
    setInt(d, "boxHeight", interleaved && s.blur ? st.patternY : 1);
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
