#pragma once
// The scheduling part of the bdpt backend, and its estimate of Pc, the power reaching the
// camera, which normalises the Metropolis backends (DESIGN.md).
//
// A pass traces, for every pixel, one camera subpath through a uniformly jittered point of the
// pixel and one light subpath, so `--spp N` is N camera samples per pixel plus N light subpaths
// per pixel. Tiles run in parallel; each pixel's samples (a scrambled Sobol sequence per pixel
// and film half) depend only on (seed, pass, pixel) and the light-tracing splats of each tile are added to the film in tile order after
// the pass, so a render is reproducible bit for bit whatever the number of threads.

#include "render/backend/backend.h"
#include "render/progressive/bdpt/bdpt_settings.h"

namespace lucerna {

class Film;
class RenderScene;

// One pass of bidirectional path tracing into half pass % 2 of the film (camera samples and
// light splats alike), then film.finishPass. Leaves the pass unfinished when ctx is cancelled.
void renderBdptPass(const RenderScene& scene, const BdptSettings& settings, uint64_t seed, int pass, Film& film,
                    TaskContext& ctx);

// Pc, the total power reaching the camera, as MIR (Segovia et al. 2007) uses it.
//
// Definition: Pc = (1 / (W H)) sum over pixels j of I_j, the mean pixel value of the image, per
// RGB channel, in the pixels' own unit (W sr^-1 m^-2). Equivalently it is the measurement of the
// whole image with the pinhole importance W_e = 1 / (A cos^4 theta) (A the area of the image
// plane at distance 1), i.e. the integral over image directions of L cos theta / (A cos^4 theta):
// the sum of the contributions of all light paths reaching the camera, normalised so that every
// path contributes f(path) / p(path) / (number of pixels) when it is splatted. A Metropolis
// chain whose stationary density is proportional to a path's luminance contribution then
// deposits luminance(Pc) * W * H / (number of mutations) per mutation, spread over pixels. It
// does not depend on the resolution (only on the view), so a low-resolution estimate serves.
struct CameraPower {
    Rgbd rgb{0, 0, 0};           // mean pixel value per channel
    double luminance = 0;        // SPEC.md's Y of rgb
    double samplesPerPixel = 0;  // work behind the estimate (camera samples per pixel)
};

// Pc of whatever the film holds (any backend's film; BDPT's is unbiased).
CameraPower cameraPower(const Film& film);

// Pc from `passes` BDPT passes over the scene's camera at its resolution (a RenderScene built
// at a low resolution makes this cheap), seeded by `seed`. Returns what was done if cancelled.
CameraPower estimateCameraPower(const RenderScene& scene, const BdptSettings& settings, uint64_t seed, int passes,
                                TaskContext& ctx);

std::unique_ptr<Backend> makeBdptBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
