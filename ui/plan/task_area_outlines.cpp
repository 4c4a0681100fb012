#include "ui/plan/task_area_outlines.h"

#include "core/photometry/surrounding_zones.h"
#include "render/display/plan_projection.h"

#include <QPainter>
#include <QPolygonF>

#include <stdexcept>

namespace lucerna {

namespace {
const QColor kSelection(30, 110, 230);

QPolygonF outline(const CalculationGrid& g, const std::function<QPointF(const V3d&)>& map) {
    return QPolygonF({map(g.corner), map(g.corner + g.edgeU), map(g.corner + g.edgeU + g.edgeV), map(g.corner + g.edgeV)});
}

// A zone's band (its strips tinted) and its outer edge in `style`.
void paintZone(QPainter& painter, const CalculationGrid& task, double inside, double width, const Scene& scene,
               const SceneBounds& room, const std::function<QPointF(const V3d&)>& map, QColor tint, Qt::PenStyle style,
               QColor edge) {
    try {
        const ZoneGrid zone = zoneGrid(task, inside, width, scene.metersPerUnit, room.lo, room.hi);
        painter.setPen(Qt::NoPen);
        painter.setBrush(tint);
        for (const CalculationGrid& strip : zone.strips) painter.drawPolygon(outline(strip, map));
        if (const auto outer = zoneOuterRectangle(task, inside, width, scene.metersPerUnit, room.lo, room.hi)) {
            painter.setPen(QPen(edge, 1.2, style));
            painter.setBrush(Qt::NoBrush);
            painter.drawPolygon(outline(*outer, map));
        }
    } catch (const std::invalid_argument&) {
        // A band too fine to lay out is not drawn; the dock says why when it is computed.
    }
}
}  // namespace

QColor TaskAreaOutlines::colour() { return QColor(0, 125, 90); }

void TaskAreaOutlines::paint(QPainter& painter, const SceneSnapshot& scene,
                             const std::function<QPointF(const V3d&)>& widgetOf, int selected) {
    if (!scene || scene->taskAreas.empty()) return;
    if (boundsScene_ != scene) {
        bounds_ = sceneBounds(*scene);
        boundsScene_ = scene;
    }
    const QColor c = colour();
    // Zones first, under every task area's own outline.
    for (const TaskArea& a : scene->taskAreas) {
        if (!a.surroundingMeters) continue;
        if (a.backgroundMeters)
            paintZone(painter, a.grid, *a.surroundingMeters, *a.backgroundMeters, *scene, bounds_, widgetOf,
                      QColor(c.red(), c.green(), c.blue(), 14), Qt::DotLine, c);
        paintZone(painter, a.grid, 0, *a.surroundingMeters, *scene, bounds_, widgetOf, QColor(c.red(), c.green(), c.blue(), 32),
                  Qt::DashLine, c);
    }
    for (size_t i = 0; i < scene->taskAreas.size(); ++i) {
        const TaskArea& a = scene->taskAreas[i];
        const bool chosen = int(i) == selected;
        const QPolygonF shape = outline(a.grid, widgetOf);
        painter.setPen(QPen(chosen ? kSelection : c, chosen ? 2.5 : 1.6));
        painter.setBrush(QColor(c.red(), c.green(), c.blue(), 40));
        painter.drawPolygon(shape);
        const QString name = a.activity.empty()
                                 ? QString::fromStdString(a.grid.name)
                                 : QStringLiteral("%1 (%2)").arg(QString::fromStdString(a.grid.name), QString::fromStdString(a.activity));
        // By the outline's top left corner as drawn, inside it.
        const QRectF box = shape.boundingRect();
        const QRectF text = painter.fontMetrics().boundingRect(name).adjusted(-2, 0, 2, 0);
        const QRectF at(box.topLeft() + QPointF(3, 3), text.size());
        painter.fillRect(at, QColor(255, 255, 255, 215));
        painter.setPen(chosen ? kSelection : c.darker(140));
        painter.drawText(at, Qt::AlignCenter, name);
    }
}

int TaskAreaOutlines::taskAreaAt(const Scene& scene, const QPointF& plan) {
    int best = -1;
    double bestArea = 0;
    const auto toPlan = [](const V3d& p) { return planPoint(PlanAxis::Top, p); };
    for (size_t i = 0; i < scene.taskAreas.size(); ++i) {
        const CalculationGrid& g = scene.taskAreas[i].grid;
        if (!outline(g, toPlan).containsPoint(plan, Qt::OddEvenFill)) continue;
        const double area = g.edgeU.cross(g.edgeV).length();
        if (best < 0 || area < bestArea) best = int(i), bestArea = area;
    }
    return best;
}

}  // namespace lucerna
