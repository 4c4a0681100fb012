#include "render/display/polar_diagram.h"

#include "core/photometry/goniometric_distribution.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {

constexpr double kToRad = std::numbers::pi / 180.0;

// A direction at gamma on one side of the plane (+1 right: C0 or C90; -1 left: C180 or C270);
// gamma 0 points down the page.
QPointF at(const QPointF& centre, double gammaDeg, double side, double r) {
    return centre + QPointF(side * r * std::sin(gammaDeg * kToRad), r * std::cos(gammaDeg * kToRad));
}

}  // namespace

double polarRingStep(double peak) {
    if (!(peak > 0)) return 1;
    const double decade = std::pow(10.0, std::floor(std::log10(peak)));
    for (double m : {0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0})
        if (peak / (m * decade) <= 5) return m * decade;
    return 10 * decade;
}

PolarRings polarRings(double peak) {
    PolarRings r;
    r.step = polarRingStep(peak);
    r.outer = std::max(1.0, std::ceil(peak / r.step - 1e-9)) * r.step;
    return r;
}

QPainterPath polarCurve(const GoniometricDistribution& d, double rightC, double leftC, double valuePerTableCd,
                        const QPointF& centre, double radius, double outer) {
    QPainterPath path;
    for (int i = 0; i <= 360; ++i) {
        const bool right = i <= 180;
        const double g = right ? i : 360 - i;
        const double value = d.intensity(right ? rightC : leftC, g) * valuePerTableCd;
        const QPointF q = at(centre, g, right ? 1 : -1, radius * value / outer);
        if (i == 0) path.moveTo(q);
        else path.lineTo(q);
    }
    return path;
}

PolarFrame polarFrame(const QRectF& area, const QFont& font, const QPainter& painter) {
    const QFontMetricsF fm(font, painter.device());
    const double margin = fm.height() + 4;
    return {area.center(), std::min(area.width(), area.height()) / 2.0 - margin};
}

void paintPolarDiagram(QPainter& p, const QRectF& area, const GoniometricDistribution& d, double valuePerTableCd,
                       const PolarDiagramStyle& style) {
    p.save();
    if (style.background.alpha() > 0) p.fillRect(area, style.background);
    const double peak = d.maxIntensity() * valuePerTableCd;
    const PolarFrame frame = polarFrame(area, style.font, p);
    if (!(peak > 0) || frame.radius < 10) {
        p.restore();
        return;
    }
    p.setFont(style.font);
    const QFontMetricsF fm(style.font, p.device());
    const PolarRings rings = polarRings(peak);
    const QPointF centre = frame.centre;
    const double radius = frame.radius;

    // Grid: spokes every 30 degrees, rings at the step with their values.
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(style.grid, style.gridPen));
    for (double g = 0; g <= 180; g += 30)
        for (double side : {-1.0, 1.0}) p.drawLine(centre, at(centre, g, side, radius));
    for (double ring = rings.step; ring <= rings.outer * (1 + 1e-9); ring += rings.step) {
        const double r = radius * ring / rings.outer;
        p.setPen(QPen(style.grid, style.gridPen));
        p.drawEllipse(centre, r, r);
        p.setPen(style.text);
        p.drawText(at(centre, 180, 1, r) + QPointF(0.3 * fm.height(), fm.ascent()), QString::number(ring, 'g', 4));
    }
    p.setPen(style.text);
    const QString bottom = QStringLiteral("0°"), top = QStringLiteral("180°");
    const double gap = 0.25 * fm.height();
    p.drawText(at(centre, 0, 1, radius) + QPointF(-fm.horizontalAdvance(bottom) / 2.0, fm.ascent() + gap), bottom);
    p.drawText(at(centre, 180, 1, radius) + QPointF(-fm.horizontalAdvance(top) / 2.0, -gap), top);
    p.drawText(at(centre, 90, -1, radius) + QPointF(gap, -gap), QStringLiteral("90°"));
    p.drawText(at(centre, 90, 1, radius) + QPointF(-gap - fm.horizontalAdvance(QStringLiteral("90°")), -gap),
               QStringLiteral("90°"));
    p.drawText(QPointF(area.right() - fm.horizontalAdvance(style.unit) - gap, area.top() + fm.ascent() + gap), style.unit);

    // The two planes, each with its sample in the legend (top left).
    struct Plane {
        double right, left;
        QColor colour;
        Qt::PenStyle pen;
        QString name;
    };
    const Plane planes[] = {{0, 180, style.c0Colour, Qt::SolidLine, QStringLiteral("C0-C180")},
                            {90, 270, style.c90Colour, Qt::DashLine, QStringLiteral("C90-C270")}};
    double legendY = area.top() + fm.ascent() + gap;
    const double sample = 1.5 * fm.height();
    for (const Plane& plane : planes) {
        p.setPen(QPen(plane.colour, style.curvePen, plane.pen));
        p.setBrush(Qt::NoBrush);
        p.drawPath(polarCurve(d, plane.right, plane.left, valuePerTableCd, centre, radius, rings.outer));
        const double y = legendY - fm.ascent() / 2.0 + fm.descent() / 2.0;
        p.drawLine(QPointF(area.left() + gap, y), QPointF(area.left() + gap + sample, y));
        p.setPen(style.text);
        p.drawText(QPointF(area.left() + 2 * gap + sample, legendY), plane.name);
        legendY += fm.height();
    }
    p.restore();
}

}  // namespace lucerna
