#pragma once
// A float RGB image with optional named extra channels (SPEC.md section 3: "albedo.R", ...), and
// string metadata for the EXR header.

#include "core/math.h"

#include <map>
#include <string>
#include <vector>

namespace lucerna {

struct Image {
    int width = 0, height = 0;
    std::vector<Rgb> pixels;                              // row-major, (0,0) top-left
    std::map<std::string, std::vector<float>> channels;  // extra layers, width*height each
    std::map<std::string, std::string> attributes;       // e.g. lucerna:backend

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h), Rgb(0, 0, 0)) {}

    Rgb& at(int x, int y) { return pixels[size_t(y) * width + x]; }
    const Rgb& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
    size_t pixelCount() const { return pixels.size(); }

    // Mean over all pixels and channels (non-finite values included as they are).
    double mean() const;
    // Box-downsampled by an integer factor (each output pixel the mean of factor x factor pixels).
    Image downsampled(int factor) const;
};

}  // namespace lucerna
