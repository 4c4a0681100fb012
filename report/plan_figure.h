#pragma once
// The plan of a task area as a report draws it (a DIALux-style result plan): the room around the
// area seen from above (the faces below three quarters of the scene's height in a grey of their
// material's reflectance, walls and partitions seen edge-on as dark lines), the area's grid in
// false colour (points inside geometry hatched), iso-lux lines labelled with their level, the
// luminaires and lamps as symbols (one shape per photometric file, as the window's plan), a scale bar and, when the site gives north, a north arrow;
// a horizontal legend in lux below. A grid that is not horizontal (on a wall) is drawn in its own
// frame, u to the right and v up, without the room.

#include "report/report_data.h"

#include <QFont>
#include <QString>

#include <optional>

class QPainter;
class QRectF;

namespace lucerna {

// A zone around the task area (EN 12464-1's surrounding zone or background area,
// core/photometry/surrounding_zones.h): its strips in the area's plane, drawn as a tinted band
// with its outer edge dashed (the background area's dotted), as the window's plan draws them, and
// named in the legend.
struct PlanZone {
    QString label;                        // "Surrounding zone (0.5 m)"
    std::vector<CalculationGrid> strips;  // ZoneGrid::strips (clipped to the room)
    bool background = false;
};

// What the plan shows on the grid: a value per point (row-major, as the layout's points) in
// the legend's quantity.
struct PlanValues {
    std::vector<double> values;
    std::vector<uint8_t> insideGeometry;  // non-zero: hatched, left out (empty: none)
    GridStatistics statistics;
    QString quantity = QStringLiteral("E [lx]");
    std::vector<GlareObserver> observers;  // drawn numbered from 1, looking along their view
    std::vector<PlanZone> zones;           // around the area, under its values
    // The area's required maintained illuminance Em (lx; values in lx): the colours centre on it
    // (render/display/plan_scales.h, requirementScale) and the legend marks it. Nothing: the
    // colours follow the values (planScale).
    std::optional<double> requiredLux;
};

// `dpmm`: device pixels per millimetre, for line widths and the raster of the room.
void paintPlanFigure(QPainter& painter, const QRectF& rect, const Scene& scene, const CalculationGrid& grid,
                     const GridLayout& layout, const PlanValues& values, const QFont& font, double dpmm);
// The plan's height over its width (the legend's band not included). The view takes in the area,
// 1 m around it and its surrounding zone (a background area may run beyond the view's edge).
double planAspect(const Scene& scene, const CalculationGrid& grid, const std::vector<PlanZone>& zones = {});
// The legend's band under the plan, mm.
inline constexpr double kPlanLegendMm = 15;

}  // namespace lucerna
