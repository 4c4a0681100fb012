#pragma once
// OpenEXR images per SPEC.md section 3: 32-bit float R, G, B holding linear radiance, extra
// layers as named channels, string attributes in the header.

#include "core/image.h"

#include <stdexcept>
#include <string>

namespace lucerna {

class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Writes atomically (SPEC.md section 2): the file appears whole or not at all. Throws ImageError.
void writeExr(const std::string& path, const Image& image);

// Reads R, G, B (half or float) and any other channels as extra layers, plus string attributes.
// Throws ImageError with a one-line reason when the file cannot be read or lacks R, G or B.
Image readExr(const std::string& path);

}  // namespace lucerna
