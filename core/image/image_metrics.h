#pragma once
// The error metrics of SPEC.md section 4.

#include "core/image/image.h"

#include <string>

namespace lucerna {

struct ImageMetrics {
    double rmse = 0;
    double relmse = 0;
    double meanTest = 0;
    double meanRef = 0;
    long nonfinite = 0;   // pixels of the test image with a NaN or infinite channel
    long includedPixels = 0;
};

// Requires equal sizes (throws std::invalid_argument otherwise). A pixel is excluded when any of
// its R, G, B in test or in reference is not finite.
ImageMetrics compareImages(const Image& test, const Image& reference);

// "rmse: ...\nrelmse: ...\n..." with 9 significant digits, in SPEC.md's order.
std::string formatMetrics(const ImageMetrics& m);

}  // namespace lucerna
