#pragma once
// The plan's key of its types of lights: one line per type, its symbol and its count
// ("[] office_panel x84"), on an opaque box, so that panels and pendants read apart.

#include "render/display/luminaire_symbols.h"

#include <QColor>
#include <QRectF>
#include <QSizeF>

class QFont;
class QPainter;

namespace lucerna {

// The key's box size in `font`; empty for a scene without positioned lights.
QSizeF lightKeySize(const PlanLightTypes& types, const QFont& font);
// The key in `box` (of lightKeySize), the symbols in `symbolColour`.
void paintLightKey(QPainter& painter, const QRectF& box, const PlanLightTypes& types, const QFont& font,
                   const QColor& symbolColour);

}  // namespace lucerna
