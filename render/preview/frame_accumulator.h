#pragma once
// Preview frames averaged, for everything that shows or measures the preview beyond one frame:
// the headless backend's passes (headless_backend.h), the illuminance layer
// (preview_illuminance.h) and the window's idle refinement (ui/rendering/live_preview.h). Each
// frame renews what the preview samples (a fresh VPL set and area-light samples, or the same
// ones dealt anew to the sub-buffers) and samples the pixel at a new point, so that the mean
// converges to the box-filtered image of the preview's model (biased still by the clamp and,
// with visibility off, by the missing VPL shadows).

#include "core/image/image.h"
#include "render/backend/film.h"
#include "render/preview/preview.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace lucerna {

// A point in the pixel drawn uniformly from the frame's seed: independent frames (the passes of
// a render, whose indices may be dealt to several processes) average to the box filter. Also
// the preview grid's (render/photometry/grid_by_preview.cpp) for its hemicubes' pixels.
V2f uniformJitter(uint64_t frameSeed);

// Frame k's point in the pixel on the R2 sequence (Roberts 2018), low-discrepancy at any
// length, so that a mean stopped early is still evenly spread; frame 0 is the pixel centre,
// where Preview::render() samples by default.
V2f sequenceJitter(int k);

// How a frame renews the preview's samples: Preview::regenerate (fresh VPLs and area-light
// samples: the VPLs' own error averages out) or Preview::redeal (the same ones dealt anew to the
// sub-buffers: only the interleaving pattern's, but no shadow map is drawn).
enum class FrameRenewal { FreshSet, NewDeal };

// One frame of a mean: the preview's samples renewed from `seed`, the pixel sampled at `jitter`
// (Preview::render). Throws what Preview::render throws.
Image drawJitteredFrame(Preview& preview, uint64_t seed, V2f jitter, FrameRenewal renewal = FrameRenewal::FreshSet);

// The sum of frames of one scene and size: radiance as a progressive film (render/backend/film.h:
// two halves, so that their difference estimates the error), and every named channel of the
// frames (the albedo layer, so that the lux view's L / albedo stays consistent at jittered
// edges). A pixel whose radiance is not finite, or a channel value that is not, adds nothing:
// it never poisons the sum, as in every backend's film.
class FrameAccumulator {
public:
    // Forgets every frame: the sum is of none, width x height pixels.
    void restart(int width, int height);
    // Adds a frame to `half` of the film (a render's passes: the pass index's parity); a frame of
    // another size than the sum's starts it over. The named channels summed are those of the
    // first frame.
    void add(const Image& frame, int half);
    // Adds a frame to the half of its place in the sequence (even frames to half 0).
    void add(const Image& frame) { add(frame, frames_ % 2); }

    // Frames added since the sum started.
    int count() const { return frames_; }
    // The mean of the frames, radiance and every named channel (black before the first), with
    // the first frame's attributes.
    Image mean() const;

    // The radiance's sums, for the headless backend's film (which a distributed render rewrites
    // in place, render/backend/pooled_films.h).
    Film& film() { return film_; }
    const Film& film() const { return film_; }

private:
    Film film_{0, 0};
    std::map<std::string, std::vector<double>> channels_;
    std::map<std::string, std::string> attributes_;
    int frames_ = 0;
};

}  // namespace lucerna
