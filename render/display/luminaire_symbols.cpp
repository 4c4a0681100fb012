#include "render/display/luminaire_symbols.h"

#include <QFileInfo>
#include <QPainter>
#include <QPolygonF>

#include <cmath>
#include <map>

namespace lucerna {

PlanLightTypes planLightTypes(const Scene& scene) {
    static const SymbolShape kLuminaireShapes[] = {SymbolShape::Square, SymbolShape::Diamond, SymbolShape::Triangle,
                                                   SymbolShape::Hexagon, SymbolShape::InvertedTriangle, SymbolShape::Circle};
    PlanLightTypes out;
    std::map<std::string, int> byKey;
    int luminaireFiles = 0;
    for (const Light& l : scene.lights) {
        if (l.type == LightType::Directional || l.type == LightType::Sun) {
            out.typeOfLight.push_back(-1);
            continue;
        }
        // A luminaire's type is its photometric file: the same product wherever it hangs.
        const bool luminaire = l.type == LightType::Luminaire && l.luminaire;
        const std::string key = luminaire ? "file:" + l.luminaire->file : l.type == LightType::Spot ? "spot" : "point";
        auto [it, added] = byKey.emplace(key, int(out.types.size()));
        if (added) {
            PlanLightType t;
            if (luminaire) {
                t.name = QFileInfo(QString::fromStdString(l.luminaire->file)).completeBaseName();
                t.shape = kLuminaireShapes[luminaireFiles++ % int(std::size(kLuminaireShapes))];
            } else {
                t.name = l.type == LightType::Spot ? QStringLiteral("Spot light") : QStringLiteral("Point light");
                t.shape = SymbolShape::Circle;
            }
            out.types.push_back(t);
        }
        ++out.types[size_t(it->second)].count;
        out.typeOfLight.push_back(it->second);
    }
    return out;
}

void paintSymbol(QPainter& painter, SymbolShape shape, const QPointF& c, double r) {
    // The polygons reach a little beyond r, so that each shape looks about as large as the square.
    const auto polygon = [&](int corners, double startDeg, double reach) {
        QPolygonF p;
        for (int k = 0; k < corners; ++k) {
            const double a = (startDeg + 360.0 * k / corners) * M_PI / 180;
            p << c + reach * r * QPointF(std::cos(a), std::sin(a));
        }
        return p;
    };
    double arm = r;  // the cross's half length: inside the shape
    switch (shape) {
    case SymbolShape::Circle: painter.drawEllipse(c, r, r); break;
    case SymbolShape::Square: painter.drawRect(QRectF(c - QPointF(r, r), c + QPointF(r, r))); break;
    case SymbolShape::Diamond: painter.drawPolygon(polygon(4, -90, 1.25)), arm = r * 0.75; break;
    // Widget y runs down: -90 degrees points up.
    case SymbolShape::Triangle: painter.drawPolygon(polygon(3, -90, 1.3)), arm = r * 0.55; break;
    case SymbolShape::InvertedTriangle: painter.drawPolygon(polygon(3, 90, 1.3)), arm = r * 0.55; break;
    case SymbolShape::Hexagon: painter.drawPolygon(polygon(6, 0, 1.1)), arm = r * 0.85; break;
    }
    painter.drawLine(c - QPointF(arm, 0), c + QPointF(arm, 0));
    painter.drawLine(c - QPointF(0, arm), c + QPointF(0, arm));
}

}  // namespace lucerna
