#include "ui/plan/light_key.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>

namespace lucerna {

namespace {
constexpr double kPad = 6, kSymbol = 12;  // pixels: the box's margin, a symbol's width

QString lineOf(const PlanLightType& t) { return QStringLiteral("%1 \u00d7%2").arg(t.name).arg(t.count); }
}  // namespace

QSizeF lightKeySize(const PlanLightTypes& types, const QFont& font) {
    if (types.types.empty()) return {};
    const QFontMetricsF fm(font);
    double text = 0;
    for (const PlanLightType& t : types.types) text = std::max(text, fm.horizontalAdvance(lineOf(t)));
    const double line = std::max(fm.height(), kSymbol + 2);
    return {2 * kPad + kSymbol + 6 + text, 2 * kPad + line * double(types.types.size())};
}

void paintLightKey(QPainter& painter, const QRectF& box, const PlanLightTypes& types, const QFont& font,
                   const QColor& symbolColour) {
    if (types.types.empty()) return;
    painter.save();
    painter.setFont(font);
    painter.setPen(QPen(QColor(120, 120, 120), 1));
    painter.setBrush(Qt::white);  // opaque: labels and the grid do not show through
    painter.drawRect(box);
    const QFontMetricsF fm(font);
    const double line = std::max(fm.height(), kSymbol + 2);
    double y = box.top() + kPad;
    for (const PlanLightType& t : types.types) {
        const QPointF c(box.left() + kPad + kSymbol / 2, y + line / 2);
        painter.setPen(QPen(symbolColour, 1.5));
        painter.setBrush(Qt::white);
        paintSymbol(painter, t.shape, c, kSymbol / 2 - 1);
        painter.setPen(Qt::black);
        painter.drawText(QRectF(box.left() + kPad + kSymbol + 6, y, box.width(), line), Qt::AlignLeft | Qt::AlignVCenter,
                         lineOf(t));
        y += line;
    }
    painter.restore();
}

}  // namespace lucerna
