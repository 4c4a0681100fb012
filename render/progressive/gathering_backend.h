#pragma once
// The common part of the backends that gather VPLs at the camera's pixels (ir, mir): the VPL
// gatherer, and the pass that takes one camera sample per pixel and gathers a set of VPLs there.

#include "render/progressive/tracing_backend.h"
#include "render/trace/rng.h"
#include "render/trace/sobol_sampler.h"
#include "render/vpl/tile_scheduler.h"
#include "render/vpl/vpl_gatherer.h"

#include <cstdint>
#include <memory>

namespace lucerna {

class GatheringBackend : public TracingBackend {
protected:
    using TracingBackend::TracingBackend;

    // Builds scene_, film_ and gatherer_; a backend that prepares more calls it first.
    void prepareGatherer(const GatherSettings& gather) {
        prepareSceneAndFilm();
        gatherer_ = std::make_unique<VplGatherer>(*scene_, gather);
    }

    // Adds one sample to every pixel of the film's half pass % 2 (not finishing the pass): a
    // camera ray through a uniformly jittered point of the pixel (box filter), gathering the VPLs
    // vplsAt(passSeed, pixel) chooses for the pixel (its index y * width + x). Each pixel's
    // numbers (its jitter, direct-light and residual samples) come from its own scrambled Sobol
    // sequence per half of the film, as path's and bdpt's do (camera_pass.h): its samples stratify
    // the pixel's edges and the first direct-light samples, and the halves stay independent, so
    // their difference is still an honest error estimate. They depend only on the seed, the pass
    // and the pixel.
    // With vplFilm, the VPL term goes there and the rest to film_ (VplGatherer::radianceParts).
    template <class VplsAt>
    void gatherPass(TaskContext& ctx, int pass, int tileSize, const VplsAt& vplsAt, Film* vplFilm = nullptr) {
        const Sensor& camera = scene_->camera();
        const int half = pass % 2;
        const uint64_t passSeed = hashSeed(settings_.seed, uint64_t(pass));
        const auto finite = [](const Rgb& L) { return isFinite(L) ? L : Rgb(0, 0, 0); };  // never poison a film
        forEachPixel(camera.width(), camera.height(), tileSize, ctx, [&](int x, int y) {
            const uint64_t pixel = uint64_t(y) * uint64_t(camera.width()) + uint64_t(x);
            SobolSampler sampler(hashSeed(settings_.seed, pixel, uint64_t(half)), uint32_t(pass / 2));
            const V2f jitter = sampler.next2D();
            const Ray ray = camera.ray(float(x) + jitter.x, float(y) + jitter.y);
            const int point = camera.pointAt(float(x) + jitter.x);
            if (!vplFilm) {
                film_->addSample(half, x, y, finite(gatherer_->radiance(ray, sampler, vplsAt(passSeed, pixel), {}, point)));
                return;
            }
            const VplGatherer::Parts L = gatherer_->radianceParts(ray, sampler, vplsAt(passSeed, pixel), point);
            film_->addSample(half, x, y, finite(L.rest));
            vplFilm->addSample(half, x, y, finite(L.vpl));
        });
    }

    std::unique_ptr<VplGatherer> gatherer_;
};

}  // namespace lucerna
