#pragma once
// The symbols plans draw lights with, one per type of light, so that a plan of a hundred
// luminaires tells its panels from its pendants: a point light is a circle, a spot a circle
// (the plan adds the wedge of its cone), and each photometric file a shape of its own (a square,
// a diamond, a triangle, ...), each with a cross at its centre; and the list of the scene's types
// with their counts, for a plan's key ("office_panel x84").

#include "core/scene/scene.h"

#include <QPointF>
#include <QString>

#include <vector>

class QPainter;

namespace lucerna {

enum class SymbolShape { Circle, Square, Diamond, Triangle, Hexagon, InvertedTriangle };

// One type of light in a scene: the point lights, the spots, or the luminaires of one
// photometric file.
struct PlanLightType {
    QString name;  // the file's name without folder and extension ("office_panel"), "Point light", "Spot light"
    SymbolShape shape = SymbolShape::Circle;
    int count = 0;  // the scene's lights of this type (switched off ones included)
};

struct PlanLightTypes {
    std::vector<PlanLightType> types;  // in the order the scene first names them
    std::vector<int> typeOfLight;   // per light of the scene: its index in `types`; -1 for directional lights and the sun
};

// The scene's types of lights. Luminaires take the shapes from the square on, in the order
// their files first appear (a seventh file takes the square again).
PlanLightTypes planLightTypes(const Scene& scene);

// The shape's outline centred on `centre`, `radius` its half width, with the cross, in the
// painter's pen and brush.
void paintSymbol(QPainter& painter, SymbolShape shape, const QPointF& centre, double radius);

}  // namespace lucerna
