#include "render/display/false_colour.h"

#include "render/display/display.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lucerna {

std::optional<Legend> luminanceLegend(const DisplaySettings& s) {
    if (!s.falseColour) return std::nullopt;
    if (s.quantity == FalseColourQuantity::Illuminance)
        return Legend{s.falseMin, s.falseMax, true,
                      s.illuminanceNote.isEmpty() ? QStringLiteral("lx") : QStringLiteral("lx, ") + s.illuminanceNote};
    return Legend{s.falseMin, s.falseMax, true, QStringLiteral("cd/m\u00b2")};
}

namespace {
// The round number (1, 2 or 5 times a power of ten) at or below x (up = false) or at or above it.
double roundNumber(double x, bool up) {
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    const double steps[] = {1, 2, 5, 10};
    if (up) {
        for (double m : steps)
            if (m * decade >= x * (1 - 1e-12)) return m * decade;
        return 10 * decade;
    }
    for (int k = 3; k >= 0; --k)
        if (steps[k] * decade <= x * (1 + 1e-12)) return steps[k] * decade;
    return decade;
}
}  // namespace

std::optional<FalseColourRange> illuminanceRange(const Image& image) {
    std::vector<double> values;
    values.reserve(image.pixelCount());
    for (size_t i = 0; i < image.pixelCount(); ++i)
        if (const auto e = pixelIlluminance(image, i); e && *e > 0) values.push_back(*e);
    if (values.empty()) return std::nullopt;
    const auto at = [&](double q) {
        const size_t k = std::min(values.size() - 1, size_t(q * double(values.size() - 1) + 0.5));
        std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
        return values[k];
    };
    FalseColourRange r;
    r.lo = roundNumber(at(0.02), false);
    r.hi = roundNumber(at(0.98), true);
    if (!(r.hi > r.lo)) r.hi = roundNumber(r.lo * 1.5, true);  // a uniform image: the next round number up
    return r;
}

double legendPosition(const Legend& legend, double value) {
    if (legend.logScale) {
        if (!(value > 0)) return 0;
        return std::clamp((std::log10(value) - std::log10(legend.lo)) / (std::log10(legend.hi) - std::log10(legend.lo)),
                          0.0, 1.0);
    }
    return std::clamp((value - legend.lo) / (legend.hi - legend.lo), 0.0, 1.0);
}

QColor legendColour(const Legend& legend, double value) { return falseColourRamp(legendPosition(legend, value)); }

QRect legendRect(const QRect& canvas) {
    // 14 px wide, leaving 70 px at the right for the labels, 34 px above for the unit (and a
    // caption) and 20 below.
    const int h = std::max(40, std::min(260, canvas.height() - 54));
    return {canvas.right() - 88, canvas.top() + 34, 14, h};
}

void paintLegend(QPainter& painter, const QRect& canvas, const Legend& legend) {
    drawLegend(painter, legendRect(canvas), legend.lo, legend.hi, legend.logScale, legend.unit);
}

}  // namespace lucerna
