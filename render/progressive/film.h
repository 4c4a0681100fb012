#pragma once
// The progressive film. It keeps two independent half-estimates, one from the even passes and
// one from the odd passes; their difference estimates the error of the combined image without a
// reference (DESIGN.md, "Speed against error").

#include "core/image.h"

#include <array>
#include <vector>

namespace lucerna {

class Film {
public:
    Film(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }

    // Adds one sample of radiance to pixel (x, y) of a half (0: even passes, 1: odd). Distinct
    // threads must write distinct pixels (tiles own their pixels).
    void addSample(int half, int x, int y, const Rgb& radiance) {
        auto& s = sums_[half][size_t(y) * width_ + x];
        s[0] += radiance.x; s[1] += radiance.y; s[2] += radiance.z;
    }
    // Declares that every pixel of `half` received `samplesPerPixel` more samples.
    void finishPass(int half, double samplesPerPixel = 1.0) { samples_[half] += samplesPerPixel; }

    double samplesPerPixel() const { return samples_[0] + samples_[1]; }

    // The combined estimate (mean of all samples).
    Image image() const;
    // One half's own estimate.
    Image halfImage(int half) const;
    // relmse of the combined image estimated from the halves: per channel (a - b)^2 / 4 over
    // (m^2 + 0.01), averaged (SPEC.md's relmse with the half difference standing in for the error).
    // Meaningful once both halves have samples; NaN before.
    double estimatedRelmse() const;

private:
    int width_, height_;
    std::array<std::vector<std::array<double, 3>>, 2> sums_;
    std::array<double, 2> samples_{0.0, 0.0};
};

}  // namespace lucerna
