#pragma once
// The legend of a false-colour picture: which values the ramp's ends stand for, on which scale,
// in which unit; where it sits on a canvas; and the colour it gives a value, so that a test (or a
// user with a colour picker) can read a pixel back against it.

#include "render/display/display.h"

#include <QColor>
#include <QRect>
#include <QString>

#include <optional>

class QPainter;

namespace lucerna {

struct Legend {
    double lo = 0, hi = 1;
    bool logScale = false;
    QString unit;
};

// The luminance legend of a display in false colour (log cd/m^2); nothing for a tone curve.
std::optional<Legend> luminanceLegend(const DisplaySettings& settings);

// The false-colour range an image's illuminance suggests (lx): its 2nd and 98th percentiles over
// the pixels that have one (pixelIlluminance, above 0), widened to round numbers (1, 2 or 5 times
// a power of ten) so that the legend's labels read plainly. Nothing when no pixel has a value.
struct FalseColourRange {
    double lo = 0, hi = 0;
};
std::optional<FalseColourRange> illuminanceRange(const Image& image);

// The ramp position of `value` (0 at lo, 1 at hi, clamped).
double legendPosition(const Legend& legend, double value);
// The colour the legend shows for `value`.
QColor legendColour(const Legend& legend, double value);
// The ramp's rectangle on a canvas of `canvas` size: the right edge, clear of the labels.
QRect legendRect(const QRect& canvas);
void paintLegend(QPainter& painter, const QRect& canvas, const Legend& legend);

}  // namespace lucerna
