#pragma once
// OpenEXR images per SPEC.md section 3: 32-bit float R, G, B holding linear radiance, extra
// layers as named channels, string attributes in the header.

#include "core/image/image.h"

#include <stdexcept>
#include <string>

namespace lucerna {

class ImageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Writes atomically (SPEC.md section 2): the file appears whole or not at all. R, G, B, then
// image.channels as 32-bit float channels under their own names (a layer "albedo" as albedo.R,
// albedo.G, albedo.B), image.attributes as string attributes. Throws ImageError, also for an
// extra channel that is empty-named, named R, G or B, or not width*height long.
void writeExr(const std::string& path, const Image& image);

// Reads R, G, B (half or float) and any other channels as extra layers, plus string attributes.
// Throws ImageError with a one-line reason when the file cannot be read or lacks R, G or B.
Image readExr(const std::string& path);

}  // namespace lucerna
