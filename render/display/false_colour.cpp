#include "render/display/false_colour.h"

#include "render/display/display.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace lucerna {

std::optional<Legend> luminanceLegend(const DisplaySettings& s) {
    if (!s.falseColour) return std::nullopt;
    return Legend{s.falseMin, s.falseMax, true,
                  s.quantity == FalseColourQuantity::Illuminance ? QStringLiteral("lx") : QStringLiteral("cd/m\u00b2")};
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
