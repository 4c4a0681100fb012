#pragma once
// Linear radiance to a displayable picture: exposure, a tone curve (linear sRGB or a filmic
// curve), or false colour of luminance in cd/m^2 (683 * Y, SPEC.md) on a log scale; and the
// difference of two images in false colour. All views and the PNG export use these, so what is
// exported is what the screen shows.

#include "core/image/image.h"
#include "render/display/legend_ticks.h"
#include "render/display/white_balance.h"

#include <QImage>
#include <QString>

#include <optional>

class QPainter;
class QRect;

namespace lucerna {

enum class ToneCurve { LinearSrgb, Filmic };

// What false colour shows: luminance in cd/m^2 (683 Y of the radiance), or illuminance in lux
// at the surface each pixel sees (pixelIlluminance).
enum class FalseColourQuantity { Luminance, Illuminance };

struct DisplaySettings {
    float exposureStops = 0.0f;
    ToneCurve curve = ToneCurve::LinearSrgb;
    bool falseColour = false;
    FalseColourQuantity quantity = FalseColourQuantity::Luminance;
    // False-colour range (cd/m^2 or lx), and how it is mapped (render/display/false_colour.h).
    double falseMin = 0.1, falseMax = 1000.0;
    LegendScale scale = LegendScale::Logarithmic;
    // Follows "lx" in the legend: which illuminance it is, "MF 0.80" (maintained) or "new"
    // (README, "Maintained values"); set from the scene, not by the display controls.
    QString illuminanceNote;
    // The picture's white (render/display/white_balance.h), before exposure and the tone curve;
    // never in false colour. `lights`: the scene's lights' colour (lightsWhite), set from the
    // scene like illuminanceNote.
    WhiteBalance white;
    Rgbd lights{1, 1, 1};
    bool operator==(const DisplaySettings&) const = default;
};

QImage toDisplayImage(const Image& image, float exposureStops = 0.0f);

// Illuminance (lux) at the surface pixel i sees: the image's `illuminance.Y` layer where it has
// one; else from the radiance and the `albedo` layer, E = pi L / albedo (in luminance: exact for
// a Lambertian surface under white light, approximate on glossy or coloured-under-coloured
// surfaces); nothing without either layer or where the albedo is under 1% (black surfaces, the
// sky, emitters, mirrors seen at an angle: no reflectance to divide by).
std::optional<double> pixelIlluminance(const Image& image, size_t i);
QImage toDisplayImage(const Image& image, const DisplaySettings& settings);

// The colour of t in [0, 1] on the false-colour ramp (blue, cyan, green, yellow, red, white).
QColor falseColourRamp(double t);

enum class DifferenceKind { Absolute, Relative };
struct DifferenceImage {
    QImage picture;
    double maxValue = 0;  // the value at the top of the legend
};
// Per pixel, the mean over channels of |a - b| (absolute) or |a - b| / (|b| + 0.01) (relative),
// in false colour from 0 to the 99th percentile. b is resampled to a's size when they differ.
DifferenceImage differenceImage(const Image& a, const Image& b, DifferenceKind kind);

// `image` resampled (nearest) to width x height: comparisons of a smaller preview with the
// converged image.
Image resampledNearest(const Image& image, int width, int height);

}  // namespace lucerna
