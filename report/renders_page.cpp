#include "report/report_pages.h"
#include "report/report_text.h"
#include "core/number_format.h"

#include "render/display/display.h"
#include "render/display/false_colour.h"

#include <QFontMetricsF>
#include <QPainter>

#include <cmath>

namespace lucerna {

namespace {

// The lux view's legend: a log ramp from lo to hi with labels at round numbers (legendTicks: 1, 2,
// 5 per decade).
void paintLuxLegend(QPainter& p, const QRectF& band, double lo, double hi, const QFont& font, double dpmm) {
    const QFontMetricsF fm(font, p.device());
    const QString unit = QStringLiteral("E [lx]");
    const double unitWidth = fm.horizontalAdvance(unit) + 3 * dpmm;
    const QRectF ramp(band.left() + unitWidth, band.top() + 1 * dpmm, band.width() - unitWidth - 8 * dpmm, 4 * dpmm);
    const Legend legend{lo, hi, true, QStringLiteral("lx")};
    const int steps = 200;
    for (int i = 0; i < steps; ++i) {
        const double t0 = double(i) / steps, t1 = double(i + 1) / steps;
        p.fillRect(QRectF(ramp.left() + t0 * ramp.width(), ramp.top(), (t1 - t0) * ramp.width() + 0.5, ramp.height()),
                   falseColourRamp((t0 + t1) / 2));
    }
    p.setPen(QPen(Qt::black, 0.15 * dpmm));
    p.setBrush(Qt::NoBrush);
    p.drawRect(ramp);
    p.setFont(font);
    p.drawText(QPointF(band.left(), ramp.center().y() + fm.ascent() / 2 - fm.descent() / 2), unit);
    double lastRight = -1e300;
    for (double v : legendTicks(legend)) {
        const double x = ramp.left() + legendPosition(legend, v) * ramp.width();
        p.drawLine(QPointF(x, ramp.bottom()), QPointF(x, ramp.bottom() + 1.2 * dpmm));
        const QString text = tickText(v);
        const double w = fm.horizontalAdvance(text);
        const double left = std::clamp(x - w / 2, band.left(), band.right() - w);
        if (left < lastRight + 1.5 * dpmm) continue;
        p.drawText(QPointF(left, ramp.bottom() + 1.6 * dpmm + fm.ascent()), text);
        lastRight = left + w;
    }
}

}  // namespace

void addRendersPage(PageFlow& flow, const ReportData& data) {
    if (!data.renders) return;
    const ReportRenders& r = *data.renders;
    flow.newPage();
    flow.heading(QStringLiteral("Renders"));
    flow.subheading(QStringLiteral("The camera's view"));
    addPicture(flow, toDisplayImage(r.converged, r.exposureStops), flow.mm(88));
    const QString target = data.settings.renderRelmse > 0
                               ? QStringLiteral(" (target %1)").arg(QString::number(data.settings.renderRelmse, 'g', 3))
                               : QString();
    flow.paragraph(QStringLiteral("Rendered by %1 (%2), %3 samples per pixel in %4, estimated relative error (relMSE) "
                                  "%5; %6 x %7 pixels; %8. Exposure %9 stops, metered on the image's log-average "
                                  "luminance.")
                       .arg(qs(r.backend), qs(r.autoReason), QString::number(r.samplesPerPixel, 'f', 0),
                            qs(formatDuration(r.seconds)), QString::number(r.estimatedRelmse, 'g', 3) + target)
                       .arg(r.converged.width)
                       .arg(r.converged.height)
                       .arg(qs(data.maintenance), QString::asprintf("%+.1f", r.exposureStops)),
                   flow.fonts().small);
    if (!(r.luxHi > r.luxLo)) return;
    flow.subheading(QStringLiteral("Lux view: illuminance on the surfaces seen"));
    DisplaySettings lux;
    lux.falseColour = true;
    lux.quantity = FalseColourQuantity::Illuminance;
    lux.falseMin = r.luxLo;
    lux.falseMax = r.luxHi;
    addPicture(flow, toDisplayImage(r.converged, lux), flow.mm(88));
    const QFont font = flow.fonts().figure;
    const double dpmm = flow.mm(1), lo = r.luxLo, hi = r.luxHi;
    flow.figure(flow.mm(10), [lo, hi, font, dpmm](QPainter& p, const QRectF& band) {
        paintLuxLegend(p, band, lo, hi, font, dpmm);
    });
    flow.paragraph(QStringLiteral("Illuminance at the surface each pixel sees, E = \u03c0 L / \u03c1 from the render's "
                                  "luminance L and the surface's reflectance \u03c1 (exact on matte surfaces under "
                                  "white light, approximate under coloured light on coloured or glossy surfaces; "
                                  "none where nothing reflects: the sky, lamps). Log scale from %1 to %2 lx (the "
                                  "view's 2nd and 98th percentiles, rounded). The task areas' figures are the "
                                  "grids', computed on their own.")
                       .arg(QString::number(r.luxLo, 'g', 6), QString::number(r.luxHi, 'g', 6)),
                   flow.fonts().small);
}

}  // namespace lucerna
