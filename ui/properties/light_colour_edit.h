#pragma once
// A light's colour as a designer gives it: a colour temperature in kelvin (a blackbody's colour)
// or a colour (linear RGB, any brightness: lights normalise it to luminance 1, so changing it
// never changes the light's flux). A mode list chooses between the two; directional lights and
// other places without a temperature key hide it.

#include "core/math.h"

#include <QWidget>

#include <optional>

class QComboBox;
class QDoubleSpinBox;

namespace lucerna {

class ColourEdit;

class LightColourEdit : public QWidget {
    Q_OBJECT
public:
    explicit LightColourEdit(QWidget* parent = nullptr);
    ~LightColourEdit() override;  // disconnects its children first (ui/disconnect_children.h)

    // Shows a temperature (when given) or a colour (white when neither), without emitting edited().
    void setValue(std::optional<double> temperatureK, const Rgbd& colour);
    // Only colours (the temperature mode hidden).
    void setColourOnly(bool only);

    bool usesTemperature() const;
    double temperatureK() const;

    QComboBox* modeField() const { return mode_; }
    QDoubleSpinBox* temperatureField() const { return temperature_; }
    ColourEdit* colourField() const { return colour_; }

signals:
    // The user changed the colour; `source` is the field that did (for undo merging).
    void edited(const void* source);
    void editingFinished();

private:
    void showMode();

    QComboBox* mode_;
    QDoubleSpinBox* temperature_;
    ColourEdit* colour_;
};

}  // namespace lucerna
