#pragma once
// The scheduling part of the path backend: tiles of the film rendered in parallel, one sample
// per pixel per pass, each pixel's random stream fixed by (seed, pass, pixel) so that a render is
// reproducible whatever the number of threads.

#include "render/progressive/backend.h"

namespace lucerna {

std::unique_ptr<ProgressiveBackend> makePathBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
