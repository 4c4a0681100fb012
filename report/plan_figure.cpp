#include "report/plan_figure.h"

#include "core/scene/scene_geometry.h"
#include "render/display/display.h"
#include "render/display/false_colour.h"
#include "render/display/iso_lines.h"
#include "render/display/legend_ticks.h"
#include "render/display/luminaire_symbols.h"
#include "render/display/plan_projection.h"
#include "render/display/plan_scales.h"

#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QTransform>

#include <algorithm>
#include <array>
#include <cmath>

namespace lucerna {

namespace {

constexpr double kRoomRasterDpmm = 8; // the room's raster, about 200 dpi
const QColor kWall(55, 55, 60);
const QColor kGlass(70, 150, 230);
const QColor kObserver(110, 20, 140);
const QColor kIsoLine(0, 0, 0);
const QColor kLuminaire(20, 30, 110);
const QColor kZone(0, 125, 90);  // the window's plan draws task areas and their zones in it

// How the figure maps the world: the plan (x right, z down, seen from above) for a horizontal
// grid, else the grid's own frame (u right, v up).
struct PlanFrame {
    bool plan = true;
    V3d origin, uHat, vHat;
    double u0 = 0, v0 = 0, scale = 1;  // figure position = offset + (coordinate - (u0, v0)) * scale
    QPointF offset;

    QPointF coordinate(const V3d& p) const {
        if (plan) return planPoint(PlanAxis::Top, p);
        const V3d d = p - origin;
        return {d.dot(uHat), -d.dot(vHat)};
    }
    QPointF at(const V3d& p) const {
        const QPointF c = coordinate(p);
        return offset + QPointF(c.x() - u0, c.y() - v0) * scale;
    }
};

// The four corners of a grid's rectangle, in order around it.
std::array<V3d, 4> cornersOf(const CalculationGrid& g) {
    return {g.corner, g.corner + g.edgeU, g.corner + g.edgeU + g.edgeV, g.corner + g.edgeV};
}

// The view's extent in the frame's coordinates: the area, 1 m around it and its surrounding
// zone (not the background area, whose 3 m would shrink the area), within the room's plan.
void viewExtent(const Scene& scene, const CalculationGrid& g, const std::vector<PlanZone>& zones, const PlanFrame& frame,
                double& u0, double& u1, double& v0, double& v1) {
    const V3d corners[4] = {g.corner, g.corner + g.edgeU, g.corner + g.edgeV, g.corner + g.edgeU + g.edgeV};
    u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (const V3d& c : corners) {
        const QPointF q = frame.coordinate(c);
        u0 = std::min(u0, q.x()), u1 = std::max(u1, q.x()), v0 = std::min(v0, q.y()), v1 = std::max(v1, q.y());
    }
    if (frame.plan) {
        // A little beyond the room's bounds, so that its outer walls show whole.
        const double margin = 1.0 / scene.metersPerUnit, beyond = 0.15 / scene.metersPerUnit;
        const double pad = 0.25 / scene.metersPerUnit;  // beyond the surrounding zone's edge
        double lo0 = u0 - margin, hi0 = u1 + margin, lo1 = v0 - margin, hi1 = v1 + margin;
        for (const PlanZone& z : zones)
            for (const CalculationGrid& strip : z.strips)
                for (const V3d& c : cornersOf(strip)) {
                    if (z.background) continue;
                    const QPointF q = frame.coordinate(c);
                    lo0 = std::min(lo0, q.x() - pad), hi0 = std::max(hi0, q.x() + pad);
                    lo1 = std::min(lo1, q.y() - pad), hi1 = std::max(hi1, q.y() + pad);
                }
        const SceneBounds b = sceneBounds(scene);
        u0 = std::max(lo0, std::min(u0, b.lo.x - beyond)), u1 = std::min(hi0, std::max(u1, b.hi.x + beyond));
        v0 = std::max(lo1, std::min(v0, b.lo.z - beyond)), v1 = std::min(hi1, std::max(v1, b.hi.z + beyond));
    }
}

// A zone's outer edge: the rectangle, in the task area's directions, around its strips.
QPolygonF zoneOutline(const CalculationGrid& task, const PlanZone& zone, const PlanFrame& frame) {
    const V3d uHat = task.edgeU.normalized(), vHat = task.edgeV.normalized();
    double s0 = 1e300, s1 = -1e300, t0 = 1e300, t1 = -1e300;
    for (const CalculationGrid& strip : zone.strips)
        for (const V3d& c : cornersOf(strip)) {
            const V3d d = c - task.corner;
            s0 = std::min(s0, d.dot(uHat)), s1 = std::max(s1, d.dot(uHat));
            t0 = std::min(t0, d.dot(vHat)), t1 = std::max(t1, d.dot(vHat));
        }
    if (s0 > s1) return {};
    const auto at = [&](double s, double t) { return frame.at(task.corner + uHat * s + vHat * t); };
    return QPolygonF({at(s0, t0), at(s1, t0), at(s1, t1), at(s0, t1)});
}

QPen zonePen(const PlanZone& zone, double dpmm) {
    QPen pen(kZone, 0.3 * dpmm);
    pen.setDashPattern(zone.background ? QList<qreal>{1.2, 2.5} : QList<qreal>{6, 3});  // in pen widths
    return pen;
}

QColor zoneTint(const PlanZone& zone) { return QColor(kZone.red(), kZone.green(), kZone.blue(), zone.background ? 22 : 50); }

// The zones as the window's plan draws them: each band tinted, its outer edge dashed (the
// background area's dotted), the background first, within the view.
void paintZones(QPainter& p, const QRectF& view, const CalculationGrid& task, const std::vector<PlanZone>& zones,
                const PlanFrame& frame, double dpmm) {
    p.save();
    p.setClipRect(view, Qt::IntersectClip);
    for (int pass = 0; pass < 2; ++pass)
        for (const PlanZone& z : zones) {
            if (z.background != (pass == 0)) continue;
            p.setPen(Qt::NoPen);
            p.setBrush(zoneTint(z));
            for (const CalculationGrid& strip : z.strips) {
                QPolygonF band;
                for (const V3d& c : cornersOf(strip)) band << frame.at(c);
                p.drawPolygon(band);
            }
            p.setPen(zonePen(z, dpmm));
            p.setBrush(Qt::NoBrush);
            p.drawPolygon(zoneOutline(task, z, frame));
        }
    p.restore();
}

PlanFrame frameOf(const CalculationGrid& g) {
    PlanFrame frame;
    frame.plan = std::abs(g.normal().y) > 0.9;
    frame.origin = g.corner;
    frame.uHat = g.edgeU.normalized();
    frame.vHat = g.edgeV.normalized();
    return frame;
}

// The values with the points inside geometry filled from their neighbours, so that iso lines do
// not ring them.
std::vector<double> filledValues(const PlanValues& plan, int nu, int nv) {
    std::vector<double> v = plan.values;
    const std::vector<uint8_t>& inside = plan.insideGeometry;
    if (inside.size() != v.size()) return v;
    std::vector<uint8_t> known(v.size());
    for (size_t k = 0; k < v.size(); ++k) known[k] = !inside[k];
    for (bool changed = true; changed;) {
        changed = false;
        std::vector<uint8_t> next = known;
        for (int j = 0; j < nv; ++j)
            for (int i = 0; i < nu; ++i) {
                const size_t k = size_t(j) * size_t(nu) + size_t(i);
                if (known[k]) continue;
                double sum = 0;
                int n = 0;
                const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
                for (int d = 0; d < 4; ++d) {
                    const int a = i + di[d], b = j + dj[d];
                    if (a < 0 || b < 0 || a >= nu || b >= nv) continue;
                    const size_t m = size_t(b) * size_t(nu) + size_t(a);
                    if (known[m]) sum += v[m], ++n;
                }
                if (n > 0) v[k] = sum / n, next[k] = 1, changed = true;
            }
        known = std::move(next);
    }
    return v;
}

// The false colour of the values over the lattice, `perCell` raster pixels to a grid cell,
// bilinear between the points and constant beyond the outer ones (to the area's edges).
QImage falseColourRaster(const std::vector<double>& values, int nu, int nv, const Legend& legend) {
    const int perCell = std::max(1, std::min(16, 1600 / std::max(nu, nv)));
    QImage image(nu * perCell, nv * perCell, QImage::Format_RGB32);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const double fi = std::clamp((x + 0.5) / perCell - 0.5, 0.0, double(nu - 1));
            const double fj = std::clamp((y + 0.5) / perCell - 0.5, 0.0, double(nv - 1));
            const int i0 = std::min(int(fi), std::max(nu - 2, 0)), j0 = std::min(int(fj), std::max(nv - 2, 0));
            const int i1 = std::min(i0 + 1, nu - 1), j1 = std::min(j0 + 1, nv - 1);
            const double ti = fi - i0, tj = fj - j0;
            const auto at = [&](int i, int j) { return values[size_t(j) * size_t(nu) + size_t(i)]; };
            const double v = (1 - tj) * ((1 - ti) * at(i0, j0) + ti * at(i1, j0)) + tj * ((1 - ti) * at(i0, j1) + ti * at(i1, j1));
            image.setPixelColor(x, y, legendColour(legend, v));
        }
    return image;
}

// The room below the cut, as a raster of `size` pixels covering the frame's view.
QImage roomRaster(const Scene& scene, const PlanFrame& frame, const QRectF& view, double dpmm) {
    const double k = kRoomRasterDpmm / dpmm;  // raster pixels per device pixel
    QImage image(std::max(1, int(view.width() * k)), std::max(1, int(view.height() * k)), QImage::Format_RGB32);
    image.fill(QColor(255, 255, 255));
    // Plan coordinates to the raster's pixels: the frame's mapping, from the view's corner.
    const QTransform toRaster = QTransform::fromTranslate(-frame.u0, -frame.v0) * QTransform::fromScale(frame.scale, frame.scale) *
                                QTransform::fromTranslate(frame.offset.x() - view.left(), frame.offset.y() - view.top()) *
                                QTransform::fromScale(k, k);
    const std::vector<PlanFace> faces = planFaces(scene, PlanAxis::Top, PlanShading::Grey);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    paintPlanFills(p, faces, toRaster, QRectF(image.rect()), 0.6);
    // Walls and partitions seen edge-on as dark lines, windows blue.
    const QPen wall(kWall, std::max(1.0, 0.35 * kRoomRasterDpmm)), window(kGlass, std::max(1.0, 0.5 * kRoomRasterDpmm));
    paintPlanWalls(p, faces, toRaster, wall, window);
    return image;
}

QString levelText(double level) { return QString::number(level, 'g', 6); }

// The zones' entries at the right of the legend's band, one under the other: a sample of the
// band and its edge, and the zone's name. Returns their width.
double paintZoneEntries(QPainter& p, const QRectF& band, const std::vector<PlanZone>& zones, const QFont& font, double dpmm) {
    if (zones.empty()) return 0;
    const QFontMetricsF fm(font, p.device());
    const double sample = 5 * dpmm, gap = 1.5 * dpmm;
    double textWidth = 0;
    for (const PlanZone& z : zones) textWidth = std::max(textWidth, fm.horizontalAdvance(z.label));
    const double width = sample + gap + textWidth, left = band.right() - width;
    double y = band.top() + 1.5 * dpmm;
    p.setFont(font);
    for (const PlanZone& z : zones) {
        const QRectF box(left, y + (fm.height() - 2.5 * dpmm) / 2, sample, 2.5 * dpmm);
        p.fillRect(box, zoneTint(z));
        p.setPen(zonePen(z, dpmm));
        p.setBrush(Qt::NoBrush);
        p.drawRect(box);
        p.setPen(Qt::black);
        p.drawText(QPointF(left + sample + gap, y + fm.ascent()), z.label);
        y += fm.height() * 1.25;
    }
    return width + 4 * dpmm;
}

void paintLegend(QPainter& p, const QRectF& band, const Legend& legend, const QString& unit, const QFont& font,
                 double dpmm, const std::vector<PlanZone>& zones) {
    const QFontMetricsF fm(font, p.device());
    const double unitWidth = fm.horizontalAdvance(unit) + 3 * dpmm;
    const double zonesWidth = paintZoneEntries(p, band, zones, font, dpmm);
    const QRectF ramp(band.left() + unitWidth, band.top() + 2 * dpmm,
                      band.width() - unitWidth - std::max(8 * dpmm, zonesWidth), 4 * dpmm);
    const int steps = 200;
    for (int i = 0; i < steps; ++i) {
        const double t0 = double(i) / steps, t1 = double(i + 1) / steps;
        const QRectF cell(ramp.left() + t0 * ramp.width(), ramp.top(), (t1 - t0) * ramp.width() + 0.5, ramp.height());
        // A banded legend's colour is its band's: the one of the value at the cell's middle.
        const size_t bands = legend.bands.size() >= 2 ? legend.bands.size() - 1 : 0;
        const double t = (t0 + t1) / 2;
        p.fillRect(cell, bands ? falseColourRamp((std::min(std::floor(t * double(bands)), double(bands) - 1) + 0.5) / double(bands))
                               : falseColourRamp(t));
    }
    p.setPen(QPen(Qt::black, 0.15 * dpmm));
    p.setBrush(Qt::NoBrush);
    p.drawRect(ramp);
    p.setFont(font);
    p.drawText(QPointF(band.left(), ramp.center().y() + fm.ascent() / 2 - fm.descent() / 2), unit);
    const double labelsRight = zonesWidth > 0 ? ramp.right() + 2 * dpmm : band.right();  // clear of the zones' entries
    const double baseline = ramp.bottom() + 1.6 * dpmm + fm.ascent();
    std::vector<std::pair<double, double>> taken;  // the labels' horizontal extents
    const auto free = [&](double left, double right) {
        return std::none_of(taken.begin(), taken.end(),
                            [&](const auto& r) { return left < r.second + 1.5 * dpmm && right > r.first - 1.5 * dpmm; });
    };
    // The requirement first, across the ramp and in bold under it: the tick labels give way.
    if (legend.target && *legend.target >= legend.lo && *legend.target <= legend.hi) {
        const double x = ramp.left() + legendPosition(legend, *legend.target) * ramp.width();
        p.setPen(QPen(Qt::white, 0.6 * dpmm));
        p.drawLine(QPointF(x, ramp.top()), QPointF(x, ramp.bottom()));
        p.setPen(QPen(Qt::black, 0.3 * dpmm));
        p.drawLine(QPointF(x, ramp.top() - 0.8 * dpmm), QPointF(x, ramp.bottom() + 1.2 * dpmm));
        QFont bold = font;
        bold.setBold(true);
        const QFontMetricsF bm(bold, p.device());
        const double w = bm.horizontalAdvance(legend.targetLabel);
        const double left = std::clamp(x - w / 2, band.left(), labelsRight - w);
        p.setFont(bold);
        p.drawText(QPointF(left, baseline), legend.targetLabel);
        p.setFont(font);
        taken.push_back({left, left + w});
    }
    p.setPen(QPen(Qt::black, 0.15 * dpmm));
    for (double v : legendTicks(legend)) {
        const double x = ramp.left() + legendPosition(legend, v) * ramp.width();
        p.drawLine(QPointF(x, ramp.bottom()), QPointF(x, ramp.bottom() + 1.2 * dpmm));
        const QString text = tickText(v);
        const double w = fm.horizontalAdvance(text);
        const double left = std::clamp(x - w / 2, band.left(), labelsRight - w);
        if (!free(left, left + w)) continue;  // labels never overlap
        p.drawText(QPointF(left, baseline), text);
        taken.push_back({left, left + w});
    }
}

// The glare observers: an eye (a ring with its number) and an arrow along its line of sight.
void paintObservers(QPainter& p, const QRectF& view, const PlanFrame& frame, const std::vector<GlareObserver>& observers,
                    const QFont& font, double dpmm) {
    const double r = 1.9 * dpmm;
    for (size_t i = 0; i < observers.size(); ++i) {
        const GlareObserver& o = observers[i];
        const QPointF c = frame.at(o.position);
        if (!view.contains(c)) continue;
        const QPointF d = frame.at(o.position + o.view.normalized()) - c;
        const double len = std::hypot(d.x(), d.y());
        p.setPen(QPen(kObserver, 0.35 * dpmm));
        if (len > 0) {
            const QPointF dir = d / len, side(-dir.y(), dir.x());
            const QPointF tip = c + dir * (r + 4 * dpmm);
            p.drawLine(c + dir * r, tip);
            QPolygonF head;
            head << tip << tip - dir * 1.4 * dpmm + side * 0.8 * dpmm << tip - dir * 1.4 * dpmm - side * 0.8 * dpmm;
            p.setBrush(kObserver);
            p.drawPolygon(head);
        }
        p.setBrush(Qt::white);
        p.drawEllipse(c, r, r);
        p.setFont(font);
        const QString n = QString::number(i + 1);
        p.drawText(QRectF(c - QPointF(r, r), QSizeF(2 * r, 2 * r)), Qt::AlignCenter, n);
    }
}

// A bar of a round length in metres at the bottom left of the plan.
void paintScaleBar(QPainter& p, const QRectF& plan, const PlanFrame& frame, double metersPerUnit, const QFont& font,
                   double dpmm) {
    const double pxPerMeter = frame.scale / metersPerUnit;
    const double meters = scaleBarMeters(pxPerMeter, plan.width() * 0.25);
    if (meters <= 0) return;
    const double len = meters * pxPerMeter;
    const QFontMetricsF fm(font, p.device());
    const QString text = QString::number(meters, 'g', 3) + QStringLiteral(" m");
    const QRectF box(plan.left() + 1 * dpmm, plan.bottom() - 7.5 * dpmm, len + 3 * dpmm + fm.horizontalAdvance(text) + 2 * dpmm,
                     6.5 * dpmm);
    p.fillRect(box, QColor(255, 255, 255, 220));
    const double y = box.bottom() - 2 * dpmm, x0 = box.left() + 1.5 * dpmm;
    p.setPen(QPen(Qt::black, 0.3 * dpmm));
    p.drawLine(QPointF(x0, y), QPointF(x0 + len, y));
    p.drawLine(QPointF(x0, y - 1.2 * dpmm), QPointF(x0, y + 0.6 * dpmm));
    p.drawLine(QPointF(x0 + len, y - 1.2 * dpmm), QPointF(x0 + len, y + 0.6 * dpmm));
    p.setFont(font);
    p.drawText(QPointF(x0 + len + 1.5 * dpmm, y + fm.ascent() / 2 - fm.descent()), text);
}

void paintNorthArrow(QPainter& p, const QRectF& plan, const PlanFrame& frame, const Site& site, const QFont& font,
                     double dpmm) {
    const QPointF d = frame.at(V3d(site.north.x, 0, site.north.z)) - frame.at(V3d(0, 0, 0));
    const double len = std::hypot(d.x(), d.y());
    if (len <= 0) return;
    const QPointF dir = d / len, side(-dir.y(), dir.x());
    const QPointF c(plan.right() - 7 * dpmm, plan.top() + 8 * dpmm);
    p.setBrush(QColor(255, 255, 255, 220));
    p.setPen(Qt::NoPen);
    p.drawEllipse(c, 6 * dpmm, 6 * dpmm);
    QPolygonF arrow;
    arrow << c + dir * 4.5 * dpmm << c - dir * 3 * dpmm + side * 2 * dpmm << c - dir * 1.5 * dpmm
          << c - dir * 3 * dpmm - side * 2 * dpmm;
    p.setBrush(Qt::black);
    p.drawPolygon(arrow);
    p.setFont(font);
    p.setPen(Qt::black);
    const QFontMetricsF fm(font, p.device());
    const QPointF n = c - dir * 5.5 * dpmm;
    p.drawText(QPointF(n.x() - fm.horizontalAdvance("N") / 2, n.y() + fm.ascent() / 2 - fm.descent() / 2), "N");
}

}  // namespace

double planAspect(const Scene& scene, const CalculationGrid& grid, const std::vector<PlanZone>& zones) {
    double u0, u1, v0, v1;
    viewExtent(scene, grid, zones, frameOf(grid), u0, u1, v0, v1);
    return (v1 - v0) / std::max(u1 - u0, 1e-9);
}

void paintPlanFigure(QPainter& p, const QRectF& rect, const Scene& scene, const CalculationGrid& g,
                     const GridLayout& layout, const PlanValues& plan, const QFont& font, double dpmm) {
    PlanFrame frame = frameOf(g);
    double u0, u1, v0, v1;
    viewExtent(scene, g, plan.zones, frame, u0, u1, v0, v1);
    const V3d corners[4] = {g.corner, g.corner + g.edgeU, g.corner + g.edgeV, g.corner + g.edgeU + g.edgeV};
    const QRectF planArea(rect.left(), rect.top(), rect.width(), rect.height() - kPlanLegendMm * dpmm);
    frame.scale = std::min(planArea.width() / std::max(u1 - u0, 1e-9), planArea.height() / std::max(v1 - v0, 1e-9));
    const QSizeF used((u1 - u0) * frame.scale, (v1 - v0) * frame.scale);
    frame.offset = QPointF(planArea.left() + (planArea.width() - used.width()) / 2, planArea.top());
    frame.u0 = u0, frame.v0 = v0;
    const QRectF view(frame.offset, used);

    if (frame.plan) p.drawImage(view, roomRaster(scene, frame, view, dpmm));
    else p.fillRect(view, Qt::white);
    paintZones(p, view, g, plan.zones, frame, dpmm);  // under the area's values

    // The grid: each point's value over its cell.
    const PlanScale scale = plan.requiredLux ? requirementScale(*plan.requiredLux, plan.statistics) : planScale(plan.statistics);
    Legend legend = scale.legend(QStringLiteral("lx"));
    if (plan.requiredLux) {
        legend.target = *plan.requiredLux;
        legend.targetLabel = QStringLiteral("Em %1").arg(tickText(*plan.requiredLux));
    }
    const int nu = layout.nu, nv = layout.nv;
    if (nu > 0 && nv > 0 && plan.values.size() == layout.points.size()) {
        const V3d du = g.edgeU / nu, dv = g.edgeV / nv;
        // The false colour between the points, bilinear in their values (as the iso lines are),
        // a raster laid on the area's quadrilateral.
        const std::vector<double> values = filledValues(plan, nu, nv);
        const QImage colours = falseColourRaster(values, nu, nv, legend);
        QTransform toArea;
        QPolygonF from, to;  // four corners each (QPolygonF of a rectangle closes it with a fifth)
        from << QPointF(0, 0) << QPointF(colours.width(), 0) << QPointF(colours.width(), colours.height())
             << QPointF(0, colours.height());
        to << frame.at(corners[0]) << frame.at(corners[1]) << frame.at(corners[3]) << frame.at(corners[2]);
        if (QTransform::quadToQuad(from, to, toArea)) {
            p.save();
            p.setTransform(toArea, true);
            p.setRenderHint(QPainter::SmoothPixmapTransform);
            p.drawImage(QPointF(0, 0), colours);
            p.restore();
        }
        // Points inside geometry hatched over their cells; the other points as dots.
        for (int j = 0; j < nv; ++j)
            for (int i = 0; i < nu; ++i) {
                const size_t k = size_t(j) * size_t(nu) + size_t(i);
                const V3d c = layout.points[k];
                if (k < plan.insideGeometry.size() && plan.insideGeometry[k]) {
                    const QPointF q[4] = {frame.at(c - du * 0.5 - dv * 0.5), frame.at(c + du * 0.5 - dv * 0.5),
                                          frame.at(c + du * 0.5 + dv * 0.5), frame.at(c - du * 0.5 + dv * 0.5)};
                    p.setPen(Qt::NoPen);
                    p.setBrush(QColor(200, 200, 200));
                    p.drawConvexPolygon(q, 4);
                    p.setBrush(QBrush(QColor(110, 110, 110), Qt::BDiagPattern));
                    p.drawConvexPolygon(q, 4);
                } else if (size_t(nu) * size_t(nv) <= 4000) {
                    p.setPen(Qt::NoPen);
                    p.setBrush(QColor(40, 40, 40, 160));
                    p.drawEllipse(frame.at(c), 0.25 * dpmm, 0.25 * dpmm);
                }
            }
        // The area's outline.
        p.setPen(QPen(Qt::black, 0.25 * dpmm));
        p.setBrush(Qt::NoBrush);
        const QPointF outline[4] = {frame.at(corners[0]), frame.at(corners[1]), frame.at(corners[3]), frame.at(corners[2])};
        p.drawConvexPolygon(outline, 4);

        // Iso-lux lines between the points, each level labelled once on its longest piece.
        const V3d origin = layout.points[0];
        const auto lattice = [&](double i, double j) { return frame.at(origin + du * i + dv * j); };
        const std::vector<IsoSegment> segments = isoSegments(values, nu, nv, scale.levels);
        p.setPen(QPen(kIsoLine, 0.3 * dpmm));
        std::vector<std::pair<double, QPointF>> labelAt(scale.levels.size(), {-1.0, QPointF()});
        for (const IsoSegment& s : segments) {
            const QPointF a = lattice(s.i0, s.j0), b = lattice(s.i1, s.j1);
            p.drawLine(a, b);
            const size_t li = size_t(std::find(scale.levels.begin(), scale.levels.end(), s.level) - scale.levels.begin());
            const double len = QLineF(a, b).length();
            if (li < labelAt.size() && len > labelAt[li].first) labelAt[li] = {len, (a + b) / 2};
        }
        p.setFont(font);
        const QFontMetricsF fm(font, p.device());
        std::vector<QRectF> placed;
        for (size_t li = 0; li < scale.levels.size(); ++li) {
            if (labelAt[li].first < 0) continue;
            const QString text = levelText(scale.levels[li]);
            const QSizeF size(fm.horizontalAdvance(text) + 1.2 * dpmm, fm.height());
            QRectF box(labelAt[li].second - QPointF(size.width() / 2, size.height() / 2), size);
            box.moveLeft(std::clamp(box.left(), view.left(), view.right() - box.width()));
            box.moveTop(std::clamp(box.top(), view.top(), view.bottom() - box.height()));
            // Lines bunched together (the edge of a sun patch) keep the first label only.
            if (std::any_of(placed.begin(), placed.end(), [&](const QRectF& r) { return r.intersects(box); })) continue;
            placed.push_back(box);
            p.fillRect(box, QColor(255, 255, 255, 225));
            p.setPen(Qt::black);
            p.drawText(box, Qt::AlignCenter, text);
        }
    }

    // Luminaires and lamps within the view.
    if (frame.plan) {
        const double r = 1.2 * dpmm;
        const PlanLightTypes types = planLightTypes(scene);
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            const Light& l = scene.lights[i];
            if (!l.on || types.typeOfLight[i] < 0) continue;
            const QPointF c = frame.at(l.position);
            if (!view.adjusted(-r, -r, r, r).contains(c)) continue;
            p.setPen(QPen(kLuminaire, 0.3 * dpmm));
            p.setBrush(QColor(255, 255, 255, 200));
            paintSymbol(p, types.types[size_t(types.typeOfLight[i])].shape, c, r);
        }
        paintObservers(p, view, frame, plan.observers, font, dpmm);
        paintScaleBar(p, view, frame, scene.metersPerUnit, font, dpmm);
        if (scene.site && scene.site->northGiven) paintNorthArrow(p, view, frame, *scene.site, font, dpmm);
    }
    p.setPen(QPen(QColor(90, 90, 90), 0.2 * dpmm));
    p.setBrush(Qt::NoBrush);
    p.drawRect(view);

    paintLegend(p, QRectF(rect.left(), rect.bottom() - (kPlanLegendMm - 2) * dpmm, rect.width(), (kPlanLegendMm - 2) * dpmm),
                legend, plan.quantity, font, dpmm, plan.zones);
}

}  // namespace lucerna
