#pragma once
// Where a plan writes its lights' names (issue 40: a plan of a hundred luminaires stays
// readable): each name beside its symbol, at the first of four places that is clear (right,
// left, above, below), or not at all. Pure geometry, without a painter, so that a test can check
// the promise on any layout.

#include <QRectF>
#include <QSizeF>

#include <optional>
#include <vector>

namespace lucerna {

struct LabelRequest {
    QRectF symbol;  // the symbol's box, widget pixels
    QSizeF size;    // the label's
};

// One result per request, in order: the label's rectangle, or nothing where none of the four
// places fits. A placed rectangle lies inside `bounds`, overlaps no obstacle (the symbols, the
// legends) and no label placed before it; requests earlier in the list are placed first.
// `gap`: pixels between a symbol and its label.
std::vector<std::optional<QRectF>> placeLabels(const std::vector<LabelRequest>& requests,
                                               const std::vector<QRectF>& obstacles, const QRectF& bounds, double gap = 3);

}  // namespace lucerna
