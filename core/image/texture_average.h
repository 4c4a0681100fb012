#pragma once
// The average colour of a texture image, for importers that keep one colour per material: a
// model's textures become the mean of their texels (linear Rec.709, sRGB decoded).

#include "core/math.h"

#include <optional>
#include <string>

namespace lucerna {

// Decodes PNG, JPEG, BMP, ... (what QImage reads) from bytes or a file; nullopt when it cannot.
// Alpha is ignored. Large images are averaged on a reduced copy (at most 256 texels a side).
std::optional<Rgbd> averageImageColour(const unsigned char* bytes, size_t size);
std::optional<Rgbd> averageImageFileColour(const std::string& path);

// Uncompressed texels (8-bit sRGB, in the given channel order of "rgba" or "bgra" bytes).
Rgbd averageTexelColour(const unsigned char* texels, size_t count, bool bgra);

}  // namespace lucerna
