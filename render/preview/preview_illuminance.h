#pragma once
// The illuminance layer (lux, render/photometry/illuminance_layer.h) as the preview sees it.

#include "render/preview/preview.h"

#include <cstdint>
#include <vector>

namespace lucerna {

// The mean of `frames` white-receiver frames (Preview::setWhiteReceivers: E / pi at every
// diffuse and glossy surface), each with fresh VPLs and a uniform point of every pixel (the box
// filter; frame_accumulator.h), times 683 pi Y. At the scene's camera or width x height, row-major
// from the top-left as Image::pixels.
std::vector<float> previewIlluminanceLayer(SceneSnapshot scene, int width, int height,
                                           const PreviewSettings& settings, int frames, uint64_t seed);

}  // namespace lucerna
