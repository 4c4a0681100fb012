#pragma once
// The scene's geometry as a plan or an elevation draws it: cut (a plan above three quarters of
// the scene's height, so that ceilings and what hangs from them do not hide the room; an
// elevation at the middle of the depth, a section), projected along an axis and ordered farthest
// first; faces filled in a light shade of their material, walls seen edge-on drawn as lines.
// One projection for the window's plan view (ui/plan) and the report's plan figures (report/),
// so that both read the room alike.

#include "core/scene/scene.h"

#include <QColor>
#include <QLineF>
#include <QPointF>

#include <vector>

class QPainter;
class QPen;
class QRectF;
class QTransform;

namespace lucerna {

// Which way a drawing looks: down -y (the plan), along -z (the front elevation), along -x (the
// side elevation).
enum class PlanAxis { Top, Front, Side };

// Plan coordinates of a world point, scene units, u to the right and w down the page: the plan
// x right and z down; the front elevation x right and y up; the side elevation z left and y up.
QPointF planPoint(PlanAxis axis, const V3d& world);
// The world displacement of a displacement in plan coordinates (none along the axis).
V3d worldDelta(PlanAxis axis, const QPointF& planDelta);

// How a drawing shades a material: a light tint of its colour (the window), or a grey, lighter
// the more it reflects (the printed report). Without a material: a middle grey.
enum class PlanShading { Tint, Grey };
QColor materialShade(const Material* material, PlanShading shading);

// One triangle of the geometry as drawn.
struct PlanFace {
    QPointF p[3];  // plan coordinates
    double depth;  // of its centroid, along the axis toward the viewer: larger is nearer
    QColor fill;   // its material's shade, darker the more it slants away from the viewer
    bool edgeOn;   // seen (nearly) edge-on, a wall in the plan: drawn as its line, not filled
    bool glass;    // of glazing or glass: a window
};

// The depth along the axis beyond which (toward the viewer) the drawing cuts the geometry away:
// three quarters of the scene's height for the plan, the middle of its depth for an elevation.
double planCut(const Scene& scene, PlanAxis axis);

// The faces of the scene's geometry not wholly beyond the cut, farthest first (faces at equal
// depth in the scene's order).
std::vector<PlanFace> planFaces(const Scene& scene, PlanAxis axis, PlanShading shading);

// The line an edge-on face stands for: its longest side (edge-on, a triangle is a sliver).
QLineF wallLine(const PlanFace& face);

// Fills the faces that are not edge-on, in order, mapped by `toDevice` (plan coordinates to the
// painter's), leaving out those wholly outside `bounds`. Each is outlined in its fill `seam`
// wide (0: a cosmetic hairline), which closes the seams between neighbouring triangles.
void paintPlanFills(QPainter& painter, const std::vector<PlanFace>& faces, const QTransform& toDevice,
                    const QRectF& bounds, double seam);
// Draws the edge-on faces as their lines: with `wall`, or with `glass` for a window.
void paintPlanWalls(QPainter& painter, const std::vector<PlanFace>& faces, const QTransform& toDevice, const QPen& wall,
                    const QPen& glass);

}  // namespace lucerna
