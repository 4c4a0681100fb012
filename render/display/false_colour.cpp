#include "render/display/false_colour.h"

#include "render/display/display.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lucerna {

Legend makeLegend(double lo, double hi, LegendScale scale, const QString& unit) {
    Legend legend{lo, hi, scale == LegendScale::Logarithmic && lo > 0, unit};
    if (scale == LegendScale::Bands) {
        legend.bands = bandEdges(lo, hi);
        if (legend.bands.size() >= 2) legend.lo = legend.bands.front(), legend.hi = legend.bands.back();
        else legend.bands.clear();
    }
    return legend;
}

std::vector<double> legendTicks(const Legend& legend) {
    if (!legend.bands.empty()) return legend.bands;
    return legendTicks(legend.lo, legend.hi, legend.logScale ? LegendScale::Logarithmic : LegendScale::Linear);
}

QString legendScaleName(LegendScale scale) {
    return scale == LegendScale::Linear        ? QStringLiteral("Linear")
           : scale == LegendScale::Logarithmic ? QStringLiteral("Logarithmic")
                                               : QStringLiteral("Bands");
}

std::optional<Legend> luminanceLegend(const DisplaySettings& s) {
    if (!s.falseColour) return std::nullopt;
    if (s.quantity == FalseColourQuantity::Illuminance)
        return makeLegend(s.falseMin, s.falseMax, s.scale,
                          s.illuminanceNote.isEmpty() ? QStringLiteral("lx") : QStringLiteral("lx, ") + s.illuminanceNote);
    return makeLegend(s.falseMin, s.falseMax, s.scale, QStringLiteral("cd/m\u00b2"));
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

namespace {
// The band holding `value` (0 .. n-1, clamped) and where in it (0 .. 1).
std::pair<size_t, double> bandOf(const std::vector<double>& edges, double value) {
    const size_t n = edges.size() - 1;
    if (!(value > edges.front())) return {0, 0.0};
    if (value >= edges.back()) return {n - 1, 1.0};
    const size_t k = size_t(std::upper_bound(edges.begin(), edges.end(), value) - edges.begin()) - 1;
    return {k, (value - edges[k]) / (edges[k + 1] - edges[k])};
}
}  // namespace

double legendPosition(const Legend& legend, double value) {
    if (legend.bands.size() >= 2) {
        const auto [k, f] = bandOf(legend.bands, value);
        return (double(k) + f) / double(legend.bands.size() - 1);
    }
    if (legend.logScale) {
        if (!(value > 0)) return 0;
        return std::clamp((std::log10(value) - std::log10(legend.lo)) / (std::log10(legend.hi) - std::log10(legend.lo)),
                          0.0, 1.0);
    }
    return std::clamp((value - legend.lo) / (legend.hi - legend.lo), 0.0, 1.0);
}

QColor legendColour(const Legend& legend, double value) {
    if (legend.bands.size() >= 2)
        return falseColourRamp((double(bandOf(legend.bands, value).first) + 0.5) / double(legend.bands.size() - 1));
    return falseColourRamp(legendPosition(legend, value));
}

QRect legendRect(const QRect& canvas) {
    // 14 px wide, leaving 70 px at the right for the labels, 34 px above for the unit (and a
    // caption) and 20 below.
    const int h = std::max(40, std::min(260, canvas.height() - 54));
    return {canvas.right() - 88, canvas.top() + 34, 14, h};
}

QRect legendFrame(const QRect& canvas) { return legendRect(canvas).adjusted(-4, -26, 74, 14); }

void paintLegend(QPainter& painter, const QRect& canvas, const Legend& legend) {
    const QRect ramp = legendRect(canvas);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, false);
    // Opaque: nothing drawn before shows through the labels.
    painter.fillRect(legendFrame(canvas), QColor(38, 38, 42));
    const int h = ramp.height();
    const size_t bands = legend.bands.size() >= 2 ? legend.bands.size() - 1 : 0;
    for (int i = 0; i < h; ++i) {
        const double t = (i + 0.5) / h;
        const QColor c = bands ? falseColourRamp((std::min(std::floor(t * double(bands)), double(bands) - 1) + 0.5) / double(bands))
                               : falseColourRamp(t);
        painter.fillRect(ramp.x(), ramp.bottom() - i, ramp.width(), 1, c);
    }
    QFont font = painter.font();
    font.setPointSizeF(8);
    painter.setFont(font);
    const QFontMetrics fm(font);
    const auto yOf = [&](double value) { return ramp.bottom() + 1 - int(std::lround(legendPosition(legend, value) * h)); };
    // The target first: the tick labels give way to it.
    std::vector<std::pair<int, int>> taken;  // the labels' vertical extents
    if (legend.target && *legend.target >= legend.lo && *legend.target <= legend.hi) {
        const int y = yOf(*legend.target);
        painter.setPen(QPen(Qt::white, 2));
        painter.drawLine(ramp.left() - 4, y, ramp.right() + 4, y);
        painter.setPen(QPen(Qt::black, 1));
        painter.drawLine(ramp.left() - 3, y, ramp.right() + 3, y);
        QFont bold = font;
        bold.setBold(true);
        painter.setFont(bold);
        painter.setPen(QColor(255, 230, 120));
        const QString text = legend.targetLabel.isEmpty() ? tickText(*legend.target) : legend.targetLabel;
        painter.drawText(ramp.right() + 6, y + fm.ascent() / 2 - 1, text);
        painter.setFont(font);
        taken.push_back({y - fm.height() / 2, y + fm.height() / 2});
    }
    painter.setPen(Qt::white);
    for (double v : legendTicks(legend)) {
        const int y = yOf(v);
        painter.drawLine(ramp.right() + 1, y, ramp.right() + 4, y);
        const int top = y - fm.height() / 2, bottom = y + fm.height() / 2;
        if (std::any_of(taken.begin(), taken.end(), [&](const auto& r) { return top < r.second && bottom > r.first; })) continue;
        taken.push_back({top, bottom});
        painter.drawText(ramp.right() + 6, y + fm.ascent() / 2 - 1, tickText(v));
    }
    painter.drawText(ramp.x(), ramp.y() - 12, legend.unit);
    painter.restore();
}

}  // namespace lucerna
