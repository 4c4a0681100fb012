#pragma once
// A luminaire's luminous intensity distribution as catalogues draw it, for every polar diagram
// drawn (the light panel's, the report's data sheets): the C0-C180 and C90-C270 planes as two
// curves in polar coordinates, gamma 0 (the nadir) at the bottom, C0 and C90 to the right of it,
// C180 and C270 to its left; rings at round values, labelled, spokes every 30 degrees, a legend
// of the two planes and the unit.

#include <QColor>
#include <QFont>
#include <QPainterPath>
#include <QRectF>
#include <QString>

class QPainter;

namespace lucerna {

struct GoniometricDistribution;

// Ring spacing for a polar plot up to `peak`: 1, 2, 2.5 or 5 times a power of ten, giving at most
// 5 rings.
double polarRingStep(double peak);

// The rings of a diagram whose largest value is `peak` (in the unit drawn): their step and the
// outer ring's value (a whole number of steps at or above the peak, at least one step).
struct PolarRings {
    double step = 1, outer = 1;
};
PolarRings polarRings(double peak);

// How a diagram is drawn on its device: the lengths are the device's pixels.
struct PolarDiagramStyle {
    QFont font;                          // labels, measured on the painter's device
    QColor background = Qt::white;       // transparent: none filled
    QColor grid = QColor(160, 160, 160); // rings and spokes
    QColor text = Qt::black;
    double gridPen = 1, curvePen = 2;
    QColor c0Colour = QColor(0, 90, 200);    // C0-C180, solid
    QColor c90Colour = QColor(200, 40, 40);  // C90-C270, dashed
    QString unit = QStringLiteral("cd");     // the values' unit, in the top right corner
};

// The plane pair's curve, closed: from the nadir up the right half (C `rightC`) to gamma 180 and
// back down the left half (C `leftC`), one point a degree, each at distance
// radius x value / outer from `centre`, value = the file's candela x `valuePerTableCd`.
QPainterPath polarCurve(const GoniometricDistribution& distribution, double rightC, double leftC,
                        double valuePerTableCd, const QPointF& centre, double radius, double outer);

// Where the diagram's circle lies within `area` for `style`: a margin of a label's height all
// round (the "0°" and "180°" labels).
struct PolarFrame {
    QPointF centre;
    double radius = 0;  // the outer ring's; below 10 px nothing is drawn
};
PolarFrame polarFrame(const QRectF& area, const QFont& font, const QPainter& painter);

// Paints the diagram of `distribution` in `area`: values the file's candela x `valuePerTableCd`
// (the scene's cd, or cd/klm), on rings of polarRings(its peak). Nothing but the background
// for a distribution whose peak is not positive.
void paintPolarDiagram(QPainter& painter, const QRectF& area, const GoniometricDistribution& distribution,
                       double valuePerTableCd, const PolarDiagramStyle& style);

}  // namespace lucerna
