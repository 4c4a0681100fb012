#include "render/preview/light_blocks.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace lucerna {

float blockImportance(const ImportanceBounds& light, const BlockBounds& block) {
    if (block.empty || light.intensity <= 0) return 0;
    // The cone: seen from the block's bounding sphere's centre with the light's own sphere grown
    // by that sphere's radius, it rules out only what no point of the block can see lit.
    const V3f centre = (block.lo + block.hi) * 0.5f;
    const float blockRadius = (block.hi - block.lo).length() * 0.5f;
    ImportanceBounds grown = light;
    const float lightRadius = std::sqrt(light.radius2), radius = lightRadius + blockRadius;
    grown.radius2 = radius * radius;
    if (!(importance(grown, centre, V3f(0, 0, 0)) > 0)) return 0;
    // The distance: from the light's sphere to the nearest point of the box (importance() measures
    // from the centre, which for a block metres wide is no bound).
    V3f nearest;
    for (int a = 0; a < 3; ++a) nearest[a] = std::clamp(light.centre[a], block.lo[a], block.hi[a]);
    const float gap = std::max((light.centre - nearest).length() - lightRadius, 1e-3f * (blockRadius + lightRadius) + 1e-6f);
    return light.intensity / (gap * gap);
}

std::vector<int32_t> chooseBlockLights(const std::vector<BlockBounds>& blocks, const LightTree& lights, int perBlock) {
    const size_t k = size_t(std::max(perBlock, 0));
    std::vector<int32_t> chosen(blocks.size() * k, -1);
    if (k == 0 || lights.empty()) return chosen;
    tbb::parallel_for(size_t(0), blocks.size(), [&](size_t b) {
        if (blocks[b].empty) return;
        const std::vector<uint32_t> strongest =
            lights.strongest([&](const ImportanceBounds& node) { return blockImportance(node, blocks[b]); }, k);
        for (size_t r = 0; r < strongest.size(); ++r) chosen[b * k + r] = int32_t(strongest[r]);
    });
    return chosen;
}

}  // namespace lucerna
