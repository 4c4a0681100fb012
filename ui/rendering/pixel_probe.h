#pragma once
// The pixel probe: the radiance (linear RGB, W/(sr m^2)), the luminance (683 * Y, cd/m^2) and,
// where the image can tell (display.h, pixelIlluminance), the illuminance (lx) of
// the pixel under the cursor, read from the float images, not from the displayed picture.

#include "core/image/image.h"

#include <QPointF>
#include <QString>

#include <optional>

namespace lucerna {

// The pixel of `image` at a normalised image point (0..1); nothing outside the image.
std::optional<QPoint> pixelAt(const Image& image, QPointF imagePoint);
// "R G B  L cd/m^2" of one pixel, 4 significant digits.
QString probeText(const Image& image, QPoint pixel);

}  // namespace lucerna
