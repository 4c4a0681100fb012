// The preview's VPLs on the GPU (gpu_state.h's tiles, shade_vpl.frag's layout): dealt to the
// interleaved sub-buffers, as a buffer and as uniform blocks, with their shadow maps.

#include "render/preview/gpu_state.h"
#include "render/trace/rng.h"

#include <algorithm>
#include <cstring>

namespace lucerna::preview_detail {

namespace {

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

}  // namespace

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

}  // namespace lucerna::preview_detail
