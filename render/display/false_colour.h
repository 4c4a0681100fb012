#pragma once
// The legend of a false-colour picture: which values the ramp's ends stand for, on which scale,
// in which unit; where it sits on a canvas; and the colour it gives a value, so that a test (or a
// user with a colour picker) can read a pixel back against it.

#include "render/display/display.h"
#include "render/display/legend_ticks.h"

#include <QColor>
#include <QRect>
#include <QString>

#include <optional>
#include <vector>

class QPainter;

namespace lucerna {

struct Legend {
    Legend() = default;
    Legend(double lo_, double hi_, bool logScale_, const QString& unit_) : lo(lo_), hi(hi_), logScale(logScale_), unit(unit_) {}

    double lo = 0, hi = 1;
    bool logScale = false;
    QString unit;
    // Discrete colour bands between these edges (ascending; lo and hi are the first and the
    // last); empty: a continuous ramp.
    std::vector<double> bands;
    // A value marked across the ramp with its label (a task area's required maintained
    // illuminance: "Em 500"); nothing: no mark.
    std::optional<double> target;
    QString targetLabel;

    LegendScale scale() const { return !bands.empty() ? LegendScale::Bands : logScale ? LegendScale::Logarithmic : LegendScale::Linear; }
};

// A legend over [lo, hi] on `scale`: Bands widens the range to the band edges (bandEdges);
// Logarithmic over a range reaching 0 or below is linear.
Legend makeLegend(double lo, double hi, LegendScale scale, const QString& unit);
// The values the legend labels (legendTicks of its range and scale; a banded one's edges).
std::vector<double> legendTicks(const Legend& legend);
// The legend's scale's name for a menu: "Linear", "Logarithmic", "Bands".
QString legendScaleName(LegendScale scale);

// The luminance (cd/m^2) or illuminance (lx) legend of a display in false colour, on the
// settings' scale; nothing for a tone curve.
std::optional<Legend> luminanceLegend(const DisplaySettings& settings);

// The false-colour range an image's illuminance suggests (lx): its 2nd and 98th percentiles over
// the pixels that have one (pixelIlluminance, above 0), widened to round numbers (1, 2 or 5 times
// a power of ten) so that the legend's labels read plainly. Nothing when no pixel has a value.
struct FalseColourRange {
    double lo = 0, hi = 0;
};
std::optional<FalseColourRange> illuminanceRange(const Image& image);

// The ramp position of `value` (0 at lo, 1 at hi, clamped). A banded legend gives each band an
// equal length, the value placed linearly within its band.
double legendPosition(const Legend& legend, double value);
// The colour the legend shows for `value` (a banded legend's: its band's, one colour each).
QColor legendColour(const Legend& legend, double value);
// The ramp's rectangle on a canvas of `canvas` size: the right edge, clear of the labels.
QRect legendRect(const QRect& canvas);
// Everything paintLegend covers (its opaque background, the unit and the labels included), so
// that a view can keep its own labels off it.
QRect legendFrame(const QRect& canvas);
// The legend, vertical at legendRect, on an opaque background: the ramp (or its bands), a tick
// and label at each of legendTicks (labels that would touch one another left out), the unit
// above and the target marked across the ramp.
void paintLegend(QPainter& painter, const QRect& canvas, const Legend& legend);

}  // namespace lucerna
