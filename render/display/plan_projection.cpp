#include "render/display/plan_projection.h"

#include "core/scene/scene_geometry.h"

#include <QPainter>
#include <QTransform>

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {

// Display sRGB of a linear value in [0, 1].
double srgb(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
}

// The colour a material shows a viewer, as a drawing hints at it: a reflector's reflectance,
// glass a pale blue, an emitter a warm white.
Rgbd appearance(const Material* m) {
    if (m) switch (m->type) {
        case MaterialType::Diffuse:
        case MaterialType::Glossy: return m->albedo;
        case MaterialType::Mirror: return m->reflectance;
        case MaterialType::Dielectric:
        case MaterialType::Glazing: return Rgbd(0.6, 0.8, 0.95);
        case MaterialType::Emitter: return Rgbd(1.0, 0.95, 0.6);
        }
    return Rgbd(0.7, 0.7, 0.7);
}

int axisIndex(PlanAxis axis) { return axis == PlanAxis::Top ? 1 : axis == PlanAxis::Front ? 2 : 0; }

}  // namespace

QPointF planPoint(PlanAxis axis, const V3d& p) {
    switch (axis) {
    case PlanAxis::Top: return {p.x, p.z};
    case PlanAxis::Front: return {p.x, -p.y};
    case PlanAxis::Side: return {-p.z, -p.y};
    }
    return {};
}

V3d worldDelta(PlanAxis axis, const QPointF& d) {
    switch (axis) {
    case PlanAxis::Top: return V3d(d.x(), 0, d.y());
    case PlanAxis::Front: return V3d(d.x(), -d.y(), 0);
    case PlanAxis::Side: return V3d(0, -d.y(), -d.x());
    }
    return V3d(0, 0, 0);
}

QColor materialShade(const Material* material, PlanShading shading) {
    const Rgbd c = appearance(material);
    if (shading == PlanShading::Grey) {
        // Pale enough that the grid's false colour and the lines over it stay the figure.
        const int g = int(std::lround(255 * (0.62 + 0.33 * std::clamp(luminance(c), 0.0, 1.0))));
        return QColor(g, g, g);
    }
    const auto channel = [](double v) { return int(std::lround(255 * (0.45 + 0.5 * srgb(v)))); };
    return QColor(channel(c.x), channel(c.y), channel(c.z));
}

double planCut(const Scene& scene, PlanAxis axis) {
    const SceneBounds b = sceneBounds(scene);
    const int k = axisIndex(axis);
    return axis == PlanAxis::Top ? b.lo.y + 0.75 * (b.hi.y - b.lo.y) : b.center[k];
}

std::vector<PlanFace> planFaces(const Scene& scene, PlanAxis axis, PlanShading shading) {
    const int k = axisIndex(axis);
    const double cut = planCut(scene, axis);
    // Slanted faces darken (the window more, where the tint alone would flatten furniture).
    const double slantDarkening = shading == PlanShading::Tint ? 25 : 12;
    V3d toward(0, 0, 0);
    toward[k] = 1;
    std::vector<PlanFace> faces;
    for (const Object& o : scene.objects) {
        if (!o.worldMesh) continue;
        const Material* material = scene.findMaterial(o.material);
        const QColor shade = materialShade(material, shading);
        const bool glass = material && (material->type == MaterialType::Glazing || material->type == MaterialType::Dielectric);
        const TriangleMesh& m = *o.worldMesh;
        for (const V3i& t : m.triangles) {
            const V3d &a = m.vertices[size_t(t.x)], &b = m.vertices[size_t(t.y)], &c = m.vertices[size_t(t.z)];
            if (std::min({a[k], b[k], c[k]}) > cut) continue;
            const V3d n = (b - a).cross(c - a);
            const double len = n.length();
            if (len <= 0) continue;
            const double facing = std::abs(n.dot(toward)) / len;
            PlanFace f{{planPoint(axis, a), planPoint(axis, b), planPoint(axis, c)}, (a[k] + b[k] + c[k]) / 3, shade,
                       facing < 0.2, glass};
            if (!f.edgeOn) f.fill = shade.darker(int(100 + slantDarkening * (1 - facing)));
            faces.push_back(f);
        }
    }
    std::stable_sort(faces.begin(), faces.end(), [](const PlanFace& x, const PlanFace& y) { return x.depth < y.depth; });
    return faces;
}

QLineF wallLine(const PlanFace& f) {
    int k0 = 0;
    double best = -1;
    for (int k = 0; k < 3; ++k) {
        const QPointF d = f.p[(k + 1) % 3] - f.p[k];
        const double l = QPointF::dotProduct(d, d);
        if (l > best) best = l, k0 = k;
    }
    return QLineF(f.p[k0], f.p[(k0 + 1) % 3]);
}

void paintPlanFills(QPainter& painter, const std::vector<PlanFace>& faces, const QTransform& toDevice, const QRectF& bounds,
                    double seam) {
    for (const PlanFace& f : faces) {
        if (f.edgeOn) continue;
        const QPointF p[3] = {toDevice.map(f.p[0]), toDevice.map(f.p[1]), toDevice.map(f.p[2])};
        // (Not QRectF::united: it drops empty rectangles, and a triangle's box may be a line.)
        const double x0 = std::min({p[0].x(), p[1].x(), p[2].x()}), x1 = std::max({p[0].x(), p[1].x(), p[2].x()});
        const double y0 = std::min({p[0].y(), p[1].y(), p[2].y()}), y1 = std::max({p[0].y(), p[1].y(), p[2].y()});
        if (x1 < bounds.left() || x0 > bounds.right() || y1 < bounds.top() || y0 > bounds.bottom()) continue;
        painter.setPen(QPen(f.fill, seam));
        painter.setBrush(f.fill);
        painter.drawConvexPolygon(p, 3);
    }
}

void paintPlanWalls(QPainter& painter, const std::vector<PlanFace>& faces, const QTransform& toDevice, const QPen& wall,
                    const QPen& glass) {
    for (const PlanFace& f : faces) {
        if (!f.edgeOn) continue;
        painter.setPen(f.glass ? glass : wall);
        painter.drawLine(toDevice.map(wallLine(f)));
    }
}

}  // namespace lucerna
