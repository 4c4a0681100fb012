#include "ui/rendering/pixel_probe.h"

#include "render/display/display.h"

#include <cmath>

namespace lucerna {

std::optional<QPoint> pixelAt(const Image& image, QPointF p) {
    if (image.width <= 0 || !(p.x() >= 0 && p.x() < 1 && p.y() >= 0 && p.y() < 1)) return std::nullopt;
    return QPoint(std::min(image.width - 1, int(std::floor(p.x() * image.width))),
                  std::min(image.height - 1, int(std::floor(p.y() * image.height))));
}

QString probeText(const Image& image, QPoint px) {
    const Rgb& c = image.at(px.x(), px.y());
    const auto n = [](double v) { return QString::number(v, 'g', 4); };
    QString text = QStringLiteral("RGB %1 %2 %3  L %4 cd/m\u00b2")
                       .arg(n(c.x), n(c.y), n(c.z), n(kLumensPerWatt * luminance(c)));
    if (const auto lux = pixelIlluminance(image, size_t(px.y()) * image.width + px.x()))
        text += QStringLiteral("  E %1 lx").arg(n(*lux));
    return text;
}

}  // namespace lucerna
