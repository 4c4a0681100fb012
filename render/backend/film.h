#pragma once
// The progressive film. It keeps two independent half-estimates, one from the even passes and
// one from the odd passes; their difference estimates the error of the combined image without a
// reference (DESIGN.md, "Speed against error").

#include "core/image/image.h"

#include <array>
#include <functional>
#include <span>
#include <vector>

namespace lucerna {

// A light-tracing contribution (bidirectional t = 1 strategies) landing on pixel (x, y): the
// pixel a light subpath's vertex projects to, not the pixel whose camera sample is running.
struct FilmSplat {
    int x = 0, y = 0;
    Rgb value{0, 0, 0};
};

class Film {
public:
    Film(int width, int height);
    // What a film of this size holds (its two half-buffers), in bytes: a render too large for
    // memory is refused before it starts.
    static double bytes(int width, int height) {
        return 2.0 * sizeof(std::array<double, 3>) * double(width) * double(height);
    }

    int width() const { return width_; }
    int height() const { return height_; }

    // Adds one sample of radiance to pixel (x, y) of a half (0: even passes, 1: odd). Distinct
    // threads must write distinct pixels (tiles own their pixels).
    void addSample(int half, int x, int y, const Rgb& radiance) {
        auto& s = sums_[half][size_t(y) * width_ + x];
        s[0] += radiance.x; s[1] += radiance.y; s[2] += radiance.z;
    }
    // Adds light-tracing splats to `half`. A pass that traces one light subpath per pixel adds
    // its splats to the same half as its camera samples, so they share the normalisation: the
    // half's sum is divided by its sample count like everything else in it. Not thread-safe by
    // design: each task collects its own list while the pass runs (so tasks never contend), and
    // the lists are added here after the pass in task order, which also keeps the rounding of
    // the sums, and so the image, independent of the number of threads.
    void addSplats(int half, std::span<const FilmSplat> splats) {
        for (const FilmSplat& s : splats) {
            auto& sum = sums_[half][size_t(s.y) * width_ + s.x];
            sum[0] += s.value.x; sum[1] += s.value.y; sum[2] += s.value.z;
        }
    }
    // Declares that every pixel of `half` received `samplesPerPixel` more samples.
    void finishPass(int half, double samplesPerPixel = 1.0) { samples_[half] += samplesPerPixel; }

    double samplesPerPixel() const { return samples_[0] + samples_[1]; }

    // Multiplies everything `half` holds, past and future, by `scale` when the film is read: for
    // Metropolis backends whose normalisation is refined as the render runs, so that old passes
    // carry the newest estimate too. 1 unless set.
    void setHalfScale(int half, double scale) { scale_[half] = scale; }

    // A film whose halves are the sums of the films' halves, each normalised by its own sample
    // count and half scale, with the first film's sample counts: the film of a scene from one
    // film per light (rendering is linear in the lights). Films of one size; an empty list gives
    // an empty 0 x 0 film.
    static Film sum(std::span<const Film* const> films);

    // The film as numbers that add (distributed renders, render/backend/pooled_films.h): each
    // half's sums times its half scale, pixel by pixel and channel by channel, then the two
    // sample counts. Adding the arrays of several films gives the array of their pooled film,
    // whose halves are the films' normalised halves averaged with weights by their samples (for
    // unit half scales, the sums of the samples and of their counts). rewriteAdditive passes
    // them, in order, a block of at most blockSize at a time, to `combine`, and makes the film
    // the one of what `combine` leaves in the blocks (its half scales 1): no copy of the whole
    // film is ever made.
    void rewriteAdditive(size_t blockSize, const std::function<void(std::span<double>)>& combine);

    // The combined estimate (mean of all samples).
    Image image() const;
    // One half's own estimate.
    Image halfImage(int half) const;
    // relmse of the combined image estimated from the halves: per pixel and channel (a - b)^2 / 4
    // (for equal halves) over (r^2 + 0.01), averaged: SPEC.md's relmse with the half difference
    // standing in for the error and the mean of the 24 pixels around it (5 x 5) for the reference r, so
    // that fireflies count as what they are (film.cpp). Meaningful once both halves have
    // samples; NaN before.
    double estimatedRelmse() const;

private:
    int width_, height_;
    std::array<std::vector<std::array<double, 3>>, 2> sums_;
    std::array<double, 2> samples_{0.0, 0.0};
    std::array<double, 2> scale_{1.0, 1.0};
};

}  // namespace lucerna
