#pragma once
// Picking a light by its symbol, as every view that draws lights picks them (the viewport over
// its picture, the plan view over its drawing): the symbol nearest the mouse within reach; and
// when a press becomes a drag.

#include <QLineF>
#include <QPointF>

#include <optional>

namespace lucerna {

// Widget pixels: a press that moves less than this is a click, not a drag.
inline constexpr double kClickSlop = 3.0;

// The light (0 to count - 1) whose symbol is nearest `pos` and at most `reach` pixels from it;
// of lights equally near, `preferred` (the one being worked on), else the last, drawn on top.
// -1 when none is in reach. `symbolOf(i)`: light i's symbol's widget position, or nothing where
// the view does not draw it.
template <class SymbolOf>
int lightNear(int count, const SymbolOf& symbolOf, const QPointF& pos, double reach, int preferred = -1) {
    int best = -1;
    double bestDistance = reach;
    for (int i = 0; i < count; ++i)
        if (const std::optional<QPointF> c = symbolOf(i)) {
            const double d = QLineF(*c, pos).length();
            if (d < bestDistance || (d <= bestDistance && (best != preferred || best < 0))) best = i, bestDistance = d;
        }
    return best;
}

}  // namespace lucerna
