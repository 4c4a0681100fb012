#pragma once
// The comparison of the live preview with the converged image: side by side under one zoom and
// pan, split by a draggable divider, or their difference (absolute or relative) in false colour
// with a legend; the relmse of the preview against the converged image (SPEC.md section 4) as a
// number; display controls; and a probe of both images' radiance under the cursor.
//
// In false colour lx the range starts from the image (its 2nd to 98th percentile, rounded:
// illuminanceRange) each time the view enters that mode, until the user sets one; with no image
// that has lux yet, from the first that does.
//
// The preview is usually smaller than the converged image; the difference and the relmse take it
// resampled (nearest) to the converged image's size, which is what the eye compares.

#include "core/image/image.h"
#include "render/display/display.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QLabel;

namespace lucerna {

class CompareCanvas;
class DisplayControls;
class ViewTransform;

class CompareView : public QWidget {
    Q_OBJECT
public:
    enum class Mode { SideBySide, Split, AbsoluteDifference, RelativeDifference };

    explicit CompareView(QWidget* parent = nullptr);

    void setPreview(Image image);
    void setConverged(Image image);
    void setMode(Mode mode);
    Mode mode() const { return mode_; }
    void setDisplaySettings(const DisplaySettings& settings);  // may fit the lux range (above)
    DisplaySettings displaySettings() const { return display_; }
    // What the lux legend says of the values (DisplaySettings::illuminanceNote).
    void setIlluminanceNote(const QString& note);
    // The scene's lights' colour (lightsWhite), for the white balance "the lights".
    void setLightsWhite(const Rgbd& lights);

    // The relmse of the preview against the converged image; nothing until both exist.
    std::optional<double> relmse() const { return relmse_; }

    // The parts, for tests and for the window's layout.
    CompareCanvas* firstCanvas() const { return first_; }
    CompareCanvas* secondCanvas() const { return second_; }
    ViewTransform* transform() const { return transform_; }
    DisplayControls* displayControls() const { return controls_; }
    QLabel* relmseLabel() const { return relmseLabel_; }
    QLabel* probeLabel() const { return probe_; }

signals:
    void displaySettingsChanged(const DisplaySettings& settings);

protected:
    void showEvent(QShowEvent*) override;

private:
    void refresh();  // the pictures, legends and relmse from the images, mode and settings
    // The range from the images when the lux view still wants one (see above); true when set.
    bool fitLuxRange(DisplaySettings& settings);
    void probe(QPointF imagePoint);

    Image preview_, converged_;
    Mode mode_ = Mode::SideBySide;
    DisplaySettings display_;
    std::optional<double> relmse_;
    bool stale_ = true;  // images changed while hidden: redraw when shown, not on every frame
    bool luxRangeByUser_ = false;  // the user set the lux range: the images no longer do
    bool luxRangeFitted_ = false;  // the range has come from an image since the lux view was entered

    ViewTransform* transform_;
    CompareCanvas *first_, *second_;
    DisplayControls* controls_;
    QComboBox* modeBox_;
    QLabel *relmseLabel_, *probe_;
};

}  // namespace lucerna
