// The viewport's overlays (ui/viewport/viewport.h): the lights' symbols, the selected lights' aim
// lines and gizmo, the selected object's outline and the active tool's hint, all clipped to the
// picture (the widget's bands beside a letterboxed picture show nothing of the scene).

#include "ui/viewport/viewport.h"

#include "core/photometry/calculation_grid.h"
#include "ui/viewport/light_placement.h"
#include "ui/viewport/light_symbols.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {
// Outlines of bigger objects would cost more than a frame to draw.
constexpr size_t kMaxOutlinedTriangles = 20000;
// Aim lines traced per frame at most (a whole selected field of luminaires).
constexpr size_t kMostAimLines = 400;

const QColor kAxisColours[3] = {QColor(235, 70, 60), QColor(90, 200, 70), QColor(70, 130, 255)};
const QColor kLightColour(255, 210, 60);
const QColor kOffColour(150, 150, 150);
}  // namespace

void Viewport::paintOverlay(QPainter& painter) {
    const QRectF picture = imageRect();
    if (picture.isEmpty()) return;
    painter.save();
    painter.setClipRect(picture);
    painter.setRenderHint(QPainter::Antialiasing);
    paintSelectedObject(painter);
    paintAimLines(painter);
    if (const auto g = gizmo()) paintGizmo(painter, *g);
    const Scene& scene = doc_->scene();
    const ViewMapping view = mapping();
    for (int i = 0; i < int(scene.lights.size()); ++i) {
        const Light& light = scene.lights[size_t(i)];
        const bool selected = i == selected_ || selectedLights_.contains(i);
        const auto symbol = selected ? lightSymbol(light, view, scene.metersPerUnit, 5.0, 8.0)
                                     : lightSymbol(light, view, scene.metersPerUnit);
        if (!symbol) continue;
        // A light switched off: a hollow grey ball. Small far ones without an outline, which
        // would be all there is of them.
        const bool small = symbol->radius < 3.5;
        if (selected) painter.setPen(QPen(Qt::white, i == selected_ ? 3 : 2));
        else if (!light.on) painter.setPen(QPen(kOffColour, small ? 1 : 1.5));
        else painter.setPen(small ? QPen(Qt::NoPen) : QPen(QColor(40, 40, 40), 1.5));
        painter.setBrush(light.on ? QBrush(kLightColour) : QBrush(Qt::NoBrush));
        painter.drawEllipse(symbol->centre, symbol->radius, symbol->radius);
    }
    paintToolHint(painter);
    painter.restore();
}

void Viewport::paintAimLines(QPainter& painter) const {
    const Scene& scene = doc_->scene();
    const ViewMapping view = mapping();
    QList<int> lights = selectedLights_.values();
    if (selected_ >= 0 && !selectedLights_.contains(selected_)) lights.append(selected_);
    if (size_t(lights.size()) > kMostAimLines) return;
    const SurfacePicker* surfaces = picker();
    const double nearDepth = nearPlaneDepth(scene.metersPerUnit);
    for (int i : lights) {
        if (i < 0 || i >= int(scene.lights.size())) continue;
        const Light& light = scene.lights[size_t(i)];
        // Not for a light whose ball is not drawn (behind or just beside the camera, outside the
        // picture): a line from there would sweep across the whole view.
        if ((light.type != LightType::Spot && light.type != LightType::Luminaire) || !lightMarker(i)) continue;
        // Dashed, to where the aim meets the scene (a ring there), or a few metres into nothing.
        const V3d d = light.direction.normalized();
        const std::optional<SurfaceHit> hit = surfaces ? surfaces->intersect(light.position, d) : std::nullopt;
        const double length = aimLineLength(hit ? std::optional(hit->distance) : std::nullopt, scene.metersPerUnit);
        const V3d end = light.position + d * length;
        const auto line = projectedSegment(view, light.position, end, nearDepth);
        if (!line) continue;
        painter.setPen(QPen(light.on ? kLightColour : kOffColour, 1.5, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        painter.drawLine(*line);
        if (hit && hit->distance <= length && depthAlongView(view, end) >= nearDepth) painter.drawEllipse(line->p2(), 4, 4);
    }
}

void Viewport::paintGizmo(QPainter& painter, const LightGizmo& g) const {
    const GizmoHandle active = drag_ == Drag::Axis || drag_ == Drag::Aim ? dragHandle_ : hoverHandle_;
    for (int i = 0; i < 3; ++i) {
        const auto& tip = g.axisTips[size_t(i)];
        if (!tip) continue;
        const bool hot = active == GizmoHandle(int(GizmoHandle::X) + i);
        painter.setPen(QPen(kAxisColours[i], hot ? 4 : 2.5, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(g.centre, *tip);
        // An arrowhead, unless the axis points nearly at the viewer and has no length on screen.
        const QPointF d = *tip - g.centre;
        const double len = std::hypot(d.x(), d.y());
        if (len < 12) continue;
        const QPointF u = d / len, n(-u.y(), u.x());
        QPainterPath head;
        head.moveTo(*tip + u * 4);
        head.lineTo(*tip - u * 9 + n * 5);
        head.lineTo(*tip - u * 9 - n * 5);
        head.closeSubpath();
        painter.setPen(Qt::NoPen);
        painter.setBrush(kAxisColours[i]);
        painter.drawPath(head);
    }
    if (g.aimTip) {
        const bool hot = active == GizmoHandle::Aim;
        painter.setPen(QPen(kLightColour, hot ? 3.5 : 2, Qt::DashLine));
        painter.drawLine(g.centre, *g.aimTip);
        painter.setPen(QPen(QColor(40, 40, 40), 1.5));
        painter.setBrush(hot ? Qt::white : kLightColour);
        painter.drawEllipse(*g.aimTip, 5.5, 5.5);
    }
}

void Viewport::paintSelectedObject(QPainter& painter) const {
    const Scene& scene = doc_->scene();
    if (selectedObject_ < 0 || selectedObject_ >= int(scene.objects.size())) return;
    const auto& mesh = scene.objects[size_t(selectedObject_)].worldMesh;
    if (!mesh || mesh->triangles.size() > kMaxOutlinedTriangles) return;
    const ViewMapping view = mapping();
    std::vector<std::optional<QPointF>> p;
    p.reserve(mesh->vertices.size());
    for (const V3d& v : mesh->vertices) p.push_back(view.toWidget(v));
    // The outline: edges of one triangle only, or between triangles that meet at an angle;
    // not the diagonals inside flat faces (a quad's).
    struct Edge {
        int a, b;
        V3d normal;
    };
    std::vector<Edge> edges;
    edges.reserve(3 * mesh->triangles.size());
    for (const V3i& t : mesh->triangles) {
        const auto& v = mesh->vertices;
        const V3d n = (v[size_t(t.y)] - v[size_t(t.x)]).cross(v[size_t(t.z)] - v[size_t(t.x)]).normalized();
        for (const auto& [a, b] : {std::pair(t.x, t.y), std::pair(t.y, t.z), std::pair(t.z, t.x)})
            edges.push_back({std::min(a, b), std::max(a, b), n});
    }
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) { return std::pair(x.a, x.b) < std::pair(y.a, y.b); });
    QPainterPath path;
    for (size_t i = 0; i < edges.size();) {
        size_t j = i + 1;
        bool crease = false;
        for (; j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b; ++j)
            crease = crease || edges[j].normal.dot(edges[i].normal) < 0.9999;
        const auto &pa = p[size_t(edges[i].a)], &pb = p[size_t(edges[i].b)];
        if ((j - i == 1 || crease) && pa && pb) {
            path.moveTo(*pa);
            path.lineTo(*pb);
        }
        i = j;
    }
    painter.setPen(QPen(QColor(110, 200, 255, 220), 1.5));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(path);
}

void Viewport::paintToolHint(QPainter& painter) const {
    if (tool_ == Tool::Navigate) return;
    const ViewMapping view = mapping();
    const Scene& scene = doc_->scene();
    if (hover_) {
        const auto at = view.toWidget(hover_->point);
        if (at && (tool_ == Tool::PlacePoint || tool_ == Tool::PlaceSpot)) {
            // Where the light would land: off the surface along its normal.
            const double offset = placementOffset(scene.metersPerUnit, picker_ ? picker_->diagonal() : 0);
            if (const auto light = view.toWidget(hover_->point + hover_->normal * offset)) {
                painter.setPen(QPen(Qt::white, 1.5, Qt::DashLine));
                painter.drawLine(*at, *light);
                painter.setPen(QPen(QColor(40, 40, 40), 1.5));
                painter.setBrush(kLightColour);
                painter.drawEllipse(*light, 5, 5);
            }
        } else if (at && tool_ == Tool::GridRectangle && gridCorner_) {
            // The rectangle the second click would make, on the first corner's surface.
            const CalculationGrid g =
                gridFromCorners(gridCorner_->point, gridCorner_->normal, hover_->point, scene.metersPerUnit, 0.0);
            QPolygonF outline;
            for (const V3d& p : {g.corner, g.corner + g.edgeU, g.corner + g.edgeU + g.edgeV, g.corner + g.edgeV})
                if (const auto w = view.toWidget(p)) outline << *w;
            painter.setPen(QPen(Qt::white, 1.5, Qt::DashLine));
            painter.setBrush(QColor(255, 255, 255, 40));
            if (outline.size() == 4) painter.drawPolygon(outline);
        } else if (at && tool_ == Tool::Aim) {
            if (const auto from = lightMarker(selected_)) {
                painter.setPen(QPen(kLightColour, 1.5, Qt::DashLine));
                painter.drawLine(*from, *at);
            }
        }
        if (at) {
            painter.setPen(QPen(Qt::white, 2));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(*at, 6, 6);
            painter.drawLine(*at - QPointF(10, 0), *at + QPointF(10, 0));
            painter.drawLine(*at - QPointF(0, 10), *at + QPointF(0, 10));
        }
    }
    const QString text =
        tool_ == Tool::PlacePoint      ? tr("Click a surface to place a point light (Esc cancels)")
        : tool_ == Tool::PlaceSpot     ? tr("Click a surface to place a spot light (Esc cancels)")
        : tool_ == Tool::GridRectangle ? (gridCorner_ ? tr("Click the opposite corner of the grid (Esc cancels)")
                                                      : tr("Click a corner of the grid on a floor, table or wall (Esc cancels)"))
                                       : tr("Click a surface to aim the light at it (Esc cancels)");
    const QRectF picture = imageRect();
    const QRectF band(picture.left(), picture.top(), picture.width(), painter.fontMetrics().height() + 10);
    painter.fillRect(band, QColor(0, 0, 0, 160));
    painter.setPen(Qt::white);
    painter.drawText(band, Qt::AlignCenter, text);
}

}  // namespace lucerna
