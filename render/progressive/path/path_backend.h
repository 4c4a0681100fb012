#pragma once
// The scheduling part of the path backend: tiles of the film rendered in parallel, one sample
// per pixel per pass, each pixel's random stream fixed by (seed, pass, pixel) so that a render is
// reproducible whatever the number of threads.

#include "render/progressive/backend.h"

namespace lucerna {

class Film;
class RenderScene;
struct PathSettings;

// One pass over the film: a path per pixel through a uniformly jittered point of the pixel,
// tiles in parallel. The pixel's random stream depends only on (seed, pass, pixel).
void renderPathPass(const RenderScene& scene, const PathSettings& settings, uint64_t seed, int pass, Film& film,
                    TaskContext& ctx);

std::unique_ptr<ProgressiveBackend> makePathBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
