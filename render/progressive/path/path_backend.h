#pragma once
// The scheduling part of the path backend: tiles of the film rendered in parallel, one sample
// per pixel per pass. Each pixel draws from a scrambled Sobol sequence fixed by (seed, pixel,
// film half), so that a render is reproducible whatever the number of threads.

#include "render/backend/backend.h"
#include "render/trace/path_settings.h"

namespace lucerna {

class Film;
class RenderScene;

// Reads "max_depth", "rr_depth" from the options; throws std::invalid_argument on bad values.
PathSettings pathSettingsFromOptions(const RenderSettings& settings);

// One pass over the film: a path per pixel through a uniformly jittered point of the pixel,
// tiles in parallel. The pixel's samples depend only on (seed, pass, pixel).
void renderPathPass(const RenderScene& scene, const PathSettings& settings, uint64_t seed, int pass, Film& film,
                    TaskContext& ctx);

std::unique_ptr<Backend> makePathBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
