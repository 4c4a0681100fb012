#pragma once
// Which delta lights the preview shades in full, block by block of the image (issue 37): in each
// block of pixels, the lights with the largest bound of their contribution to what the block
// sees, where one list for the whole frame (by nearness to the camera) dealt the lights near a
// far desk out at random. The bound uses the light tree's bounds (light_tree.h): the light's
// intensity over its nearest distance to the block, zero where its cone misses the block.
// Every light stays dealt to the sub-buffers; the direct pass takes a block's own lights' dealt
// share back out of the blurred light (resources/shaders/preview/light_blocks.glsl), so that none
// is counted twice.
//
// Pure CPU: direct_lights.cpp (chooseLightsPerBlock) finds the blocks' boxes on the GPU and
// uploads the choice.

#include "render/trace/lights/light_tree.h"

#include <cstdint>
#include <vector>

namespace lucerna {

// What a block's shaded pixels see: the box of their positions (scene units); empty when none.
struct BlockBounds {
    V3f lo{0, 0, 0}, hi{0, 0, 0};
    bool empty = true;
};

// An upper bound of the irradiance `light` can give anywhere in `block`, up to importance()'s
// common factor: its intensity over the squared distance from its sphere to the block's box
// (at least a thousandth of their sizes); 0 for an empty block or where the light's cone cannot
// reach the block's bounding sphere.
float blockImportance(const ImportanceBounds& light, const BlockBounds& block);

// Per block, the `perBlock` lights of the largest blockImportance, strongest first, by the light
// index `lights` keeps (LightTree::strongest); -1 pads a block with fewer lights that reach it
// (and fills an empty block). Blocks in parallel (oneTBB).
std::vector<int32_t> chooseBlockLights(const std::vector<BlockBounds>& blocks, const LightTree& lights, int perBlock);

}  // namespace lucerna
