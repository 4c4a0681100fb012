#pragma once
// `lucerna render --backend preview`: the interactive preview, headless. One pass is one preview
// frame with a fresh VPL set, fresh area-light samples and a uniformly jittered pixel position
// (frame_accumulator.h), so averaging passes converges to the box-filtered image of the
// preview's model (it stays biased by the clamp and, with visibility off, by the missing VPL
// shadows).
//
// Options (--option name=value; PreviewSettings says what each does): vpls (256), pattern (4x4),
// clamp (0.05, fraction of the scene radius), visibility (0/1), blur (0/1), area_samples (16),
// split (fused, one or two), vpl_source (ir or mir), unroll (16), shaded_lights (8),
// proxy_triangles (8192), sky_samples (64), sky_shadow_size (256).

#include "render/backend/backend.h"
#include "render/preview/preview.h"

namespace lucerna {

// Reads the options above into preview settings; throws std::invalid_argument on a bad value.
PreviewSettings previewSettingsFromOptions(const RenderSettings& settings);

std::unique_ptr<Backend> makePreviewBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
