#include "core/image/texture_average.h"
#include "core/regular_file.h"

#include <QImage>

#include <cmath>

namespace lucerna {

namespace {
double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

std::optional<Rgbd> average(QImage image) {
    if (image.isNull() || image.width() <= 0 || image.height() <= 0) return std::nullopt;
    // A box-filtered reduction keeps the mean close enough for one colour per material.
    if (image.width() > 256 || image.height() > 256)
        image = image.scaled(256, 256, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    image = image.convertToFormat(QImage::Format_RGB888);
    Rgbd sum(0, 0, 0);
    for (int y = 0; y < image.height(); ++y) {
        const uchar* row = image.constScanLine(y);
        for (int x = 0; x < image.width(); ++x)
            sum += Rgbd(srgbToLinear(row[3 * x] / 255.0), srgbToLinear(row[3 * x + 1] / 255.0), srgbToLinear(row[3 * x + 2] / 255.0));
    }
    return sum / double(image.width() * image.height());
}
}  // namespace

std::optional<Rgbd> averageImageColour(const unsigned char* bytes, size_t size) {
    if (!bytes || size == 0) return std::nullopt;
    return average(QImage::fromData(bytes, int(size)));
}

std::optional<Rgbd> averageImageFileColour(const std::string& path) {
    if (!nonRegularFileKind(path).empty()) return std::nullopt;  // a FIFO would block the reader forever
    return average(QImage(QString::fromStdString(path)));
}

Rgbd averageTexelColour(const unsigned char* texels, size_t count, bool bgra) {
    Rgbd sum(0, 0, 0);
    for (size_t i = 0; i < count; ++i) {
        const unsigned char* t = texels + 4 * i;
        const double r = t[bgra ? 2 : 0], g = t[1], b = t[bgra ? 0 : 2];
        sum += Rgbd(srgbToLinear(r / 255.0), srgbToLinear(g / 255.0), srgbToLinear(b / 255.0));
    }
    return count ? sum / double(count) : sum;
}

}  // namespace lucerna
