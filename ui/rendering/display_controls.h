#pragma once
// The display settings a user changes: exposure in stops, and how radiance becomes a picture
// (linear sRGB, the filmic curve, or false-colour luminance in cd/m^2 with its range and its
// scale: logarithmic, linear, or bands between round values), and the picture's white (D65, the
// scene's lights, or a colour temperature). The range's
// fields take what is typed when the typing ends (Enter or leaving the field), neither field
// moving the other; a maximum not above the minimum is refused with a message and the previous
// range kept.

#include "render/display/display.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;

namespace lucerna {

class DisplayControls : public QWidget {
    Q_OBJECT
public:
    explicit DisplayControls(QWidget* parent = nullptr);

    DisplaySettings settings() const { return settings_; }
    void setSettings(const DisplaySettings& settings);

signals:
    void settingsChanged(const DisplaySettings& settings);
    // A one-line message for the status bar (a range refused).
    void message(const QString& text);
    // The user set the false-colour range (typed or stepped), as opposed to setSettings.
    void rangeSetByUser();

private:
    void read();

    DisplaySettings settings_;
    QDoubleSpinBox *exposure_, *falseMin_, *falseMax_;
    QComboBox* mode_;
    QComboBox* scale_;  // the false colour's LegendScale
    QComboBox* white_;  // the white balance (render/display/white_balance.h)
    QWidget* rangeTo_;  // the "to" between the range's ends
};

}  // namespace lucerna
