#pragma once
// Linear radiance to a displayable picture: exposure, then the sRGB transfer curve.

#include "core/image.h"

#include <QImage>

namespace lucerna {

QImage toDisplayImage(const Image& image, float exposureStops = 0.0f);

}  // namespace lucerna
