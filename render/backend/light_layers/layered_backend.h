#pragma once
// Per-light layers for any progressive backend: one instance of the backend per light group
// (light_groups.h), each rendering the scene lit by its group alone, pass for pass in step. The
// film is their sum, so the combined image is the same estimate as a render with all lights
// (the sum of unbiased estimates of each light's part), and every frame carries each group's
// layer as named channels (light.NAME.R/G/B, group.NAME.R/G/B), which a mixer weights afterwards.
//
// The cost: each pass is one pass of every layer (and one acceleration structure per layer). The
// gain besides the mix: no layer chooses among lights, so the noise of that choice is gone; with
// several lights of similar power that can outweigh the fewer passes (BENCHMARKS.md,
// "Per-light layers (issue 7)").

#include "render/backend/backend.h"

namespace lucerna {

// The backend `base` wrapped in per-light layers. A scene without lights renders as `base`
// alone would (one layer of nothing). Throws std::invalid_argument as `base` does for bad
// settings, and with lightLayerLimitMessage() for a scene of more than kMaxLightLayers layers.
std::unique_ptr<Backend> makeLayeredBackend(BackendFactory base, SceneSnapshot scene,
                                                       const RenderSettings& settings);

}  // namespace lucerna
