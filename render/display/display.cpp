#include "render/display/display.h"

#include "render/display/false_colour.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace lucerna {

namespace {
uchar encodeSrgb(float v) {
    v = std::clamp(v, 0.0f, 1.0f);
    const float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return uchar(std::lround(s * 255.0f));
}

// A filmic curve (Narkowicz's fit of the ACES reference tone scale): a toe, a long shoulder
// that keeps highlights from clipping, applied per channel to linear values.
float filmic(float x) {
    x = std::max(x, 0.0f) * 0.6f;
    return std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

}  // namespace

QColor falseColourRamp(double t) {
    static const QColor stops[] = {QColor(0, 0, 80), QColor(0, 60, 255), QColor(0, 220, 220), QColor(0, 200, 0),
                                   QColor(255, 240, 0), QColor(255, 0, 0), QColor(255, 255, 255)};
    constexpr int n = int(std::size(stops)) - 1;
    t = std::clamp(t, 0.0, 1.0) * n;
    const int i = std::min(int(t), n - 1);
    const double f = t - i;
    const QColor& a = stops[i];
    const QColor& b = stops[i + 1];
    return QColor(int(a.red() + (b.red() - a.red()) * f), int(a.green() + (b.green() - a.green()) * f),
                  int(a.blue() + (b.blue() - a.blue()) * f));
}

QImage toDisplayImage(const Image& image, float exposureStops) {
    DisplaySettings s;
    s.exposureStops = exposureStops;
    return toDisplayImage(image, s);
}

std::optional<double> pixelIlluminance(const Image& image, size_t i) {
    if (const auto it = image.channels.find("illuminance.Y"); it != image.channels.end() && i < it->second.size())
        return std::isfinite(it->second[i]) ? std::optional<double>(it->second[i]) : std::nullopt;
    const auto r = image.channels.find("albedo.R"), g = image.channels.find("albedo.G"),
               b = image.channels.find("albedo.B");
    if (r == image.channels.end() || g == image.channels.end() || b == image.channels.end()) return std::nullopt;
    if (i >= r->second.size() || i >= image.pixels.size()) return std::nullopt;
    const double albedoY = luminance(Rgbd(r->second[i], g->second[i], b->second[i]));
    const Rgb& p = image.pixels[i];
    if (!(albedoY >= 0.01) || !isFinite(p)) return std::nullopt;
    return kLumensPerWatt * std::numbers::pi * luminance(p) / albedoY;
}

QImage toDisplayImage(const Image& image, const DisplaySettings& settings) {
    QImage out(image.width, image.height, QImage::Format_RGB888);
    const float scale = std::exp2(settings.exposureStops);
    const std::optional<Legend> legend = luminanceLegend(settings);
    const Imath::M33f balance(whiteBalanceMatrix(referenceWhite(settings.white, settings.lights)));
    const bool balanced = balance != Imath::M33f();
    for (int y = 0; y < image.height; ++y) {
        uchar* row = out.scanLine(y);
        for (int x = 0; x < image.width; ++x) {
            const Rgb& p = image.at(x, y);
            if (settings.falseColour) {
                // Photometric, so exposure does not apply: the legend reads absolute cd/m^2 or lx.
                double value = 0.0;
                if (settings.quantity == FalseColourQuantity::Illuminance)
                    value = pixelIlluminance(image, size_t(y) * image.width + x).value_or(0.0);
                else if (isFinite(p))
                    value = kLumensPerWatt * luminance(p);
                const QRgb c = legendColour(*legend, value).rgb();
                row[3 * x] = uchar(qRed(c));
                row[3 * x + 1] = uchar(qGreen(c));
                row[3 * x + 2] = uchar(qBlue(c));
                continue;
            }
            const Rgb q = balanced && isFinite(p) ? Rgb(V3f(p) * balance) : p;
            for (int c = 0; c < 3; ++c) {
                float v = std::isfinite(q[c]) ? std::max(0.0f, q[c]) * scale : 0.0f;
                if (settings.curve == ToneCurve::Filmic) v = filmic(v);
                row[3 * x + c] = encodeSrgb(v);
            }
        }
    }
    return out;
}

Image resampledNearest(const Image& image, int width, int height) {
    if (image.width == width && image.height == height) return image;
    Image out(width, height);
    if (image.width <= 0 || image.height <= 0) return out;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            out.at(x, y) = image.at(std::min(image.width - 1, x * image.width / width),
                                    std::min(image.height - 1, y * image.height / height));
    return out;
}

DifferenceImage differenceImage(const Image& a, const Image& bIn, DifferenceKind kind) {
    const Image b = resampledNearest(bIn, a.width, a.height);
    std::vector<float> d(a.pixelCount(), 0.0f);
    for (size_t i = 0; i < d.size(); ++i) {
        const Rgb& p = a.pixels[i];
        const Rgb& q = b.pixels[i];
        float sum = 0;
        for (int c = 0; c < 3; ++c) {
            const float diff = std::abs(p[c] - q[c]);
            sum += kind == DifferenceKind::Absolute ? diff : diff / (std::abs(q[c]) + 0.01f);
        }
        d[i] = std::isfinite(sum) ? sum / 3 : 0.0f;
    }
    DifferenceImage out;
    std::vector<float> sorted = d;
    if (!sorted.empty()) {
        const size_t k = std::min(sorted.size() - 1, sorted.size() * 99 / 100);
        std::nth_element(sorted.begin(), sorted.begin() + long(k), sorted.end());
        out.maxValue = std::max(double(sorted[k]), 1e-6);
    } else {
        out.maxValue = 1;
    }
    out.picture = QImage(a.width, a.height, QImage::Format_RGB888);
    for (int y = 0; y < a.height; ++y) {
        uchar* row = out.picture.scanLine(y);
        for (int x = 0; x < a.width; ++x) {
            const QColor c = falseColourRamp(d[size_t(y) * a.width + x] / out.maxValue);
            row[3 * x] = uchar(c.red());
            row[3 * x + 1] = uchar(c.green());
            row[3 * x + 2] = uchar(c.blue());
        }
    }
    return out;
}

}  // namespace lucerna
