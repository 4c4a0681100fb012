#include "ui/display.h"

namespace lucerna {

namespace {
uchar encodeSrgb(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return uchar(std::lround(s * 255.0f));
}
}  // namespace

QImage toDisplayImage(const Image& image, float exposureStops) {
    QImage out(image.width, image.height, QImage::Format_RGB888);
    const float scale = std::exp2(exposureStops);
    for (int y = 0; y < image.height; ++y) {
        uchar* row = out.scanLine(y);
        for (int x = 0; x < image.width; ++x) {
            const Rgb& p = image.at(x, y);
            for (int c = 0; c < 3; ++c) row[3 * x + c] = encodeSrgb(std::isfinite(p[c]) ? p[c] * scale : 0.0f);
        }
    }
    return out;
}

}  // namespace lucerna
