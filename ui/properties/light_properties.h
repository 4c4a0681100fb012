#pragma once
// The property panel of the selected light, in the units a designer works in: a point or spot
// light's luminous flux (lm) or on-axis intensity (cd) and its colour temperature (K) or colour,
// written into the light's photometric keys so that the file keeps what was typed; a spot's cone
// and falloff half-angles; a directional light's illuminance (lx) on a surface facing it; a
// luminaire's file, rotation, flux, colour and its distribution as a polar plot; a point, spot or
// luminaire's circuit power (W, for the lighting energy; empty: a luminaire's file's) and its own
// maintenance factor or the scene's (ui/scene_panels/maintenance_factor_edit.h). The radiometric
// values (W/sr, W/m²) are an advanced view behind a toggle. A sun shows its name, group and (when
// placed by direction) its direction; the rest of it is the daylight panel's. Lengths are in the scene's unit.
// A spot's, luminaire's or directional light's aim is a tilt from straight down and an azimuth
// from the site's north (core/scene/aim_angles.h), not the scene's direction vector.
// Every edit of a field is one EditLightCommand holding the whole light before and after; the
// arrow steps of one field merge into it until the field's editing finishes.

#include "ui/properties/item_properties.h"

#include <array>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QToolButton;

namespace lucerna {

class LightColourEdit;
class LuminairePolarPlot;
class MaintenanceFactorEdit;

class LightProperties : public ItemProperties {
    Q_OBJECT
public:
    explicit LightProperties(Document* doc, QWidget* parent = nullptr);

    // -1: no light (the panel says so).
    void setLight(int index) { select(index); }
    int light() const { return index_; }

    // The fields, for tests and for focus.
    QLineEdit* nameField() const { return name_; }
    // The group the light belongs to (empty: none); typing a name moves it there.
    QLineEdit* groupField() const { return group_; }
    const std::array<QDoubleSpinBox*, 3>& positionFields() const { return position_; }
    // The aim (spot, luminaire, directional light, a sun placed by direction): degrees from
    // straight down, 0 to 180; and the bearing in degrees clockwise from the site's north, seen
    // from above. A vertical aim has no bearing: the azimuth field then keeps what it shows, and
    // a tilt typed afterwards leans the light that way.
    QDoubleSpinBox* tiltField() const { return tilt_; }
    QDoubleSpinBox* azimuthField() const { return azimuth_; }
    // Point and spot: the flux or candela value, its unit (0 lm, 1 cd).
    QDoubleSpinBox* outputField() const { return output_; }
    QComboBox* outputUnitField() const { return outputUnit_; }
    QDoubleSpinBox* illuminanceField() const { return illuminance_; }
    LightColourEdit* colourField() const { return colour_; }
    // The advanced view: radiant intensity (W/sr) or irradiance (W/m²) per channel.
    QToolButton* advancedToggle() const { return advanced_; }
    const std::array<QDoubleSpinBox*, 3>& powerFields() const { return power_; }
    QDoubleSpinBox* coneField() const { return cone_; }
    QDoubleSpinBox* falloffField() const { return falloff_; }
    QDoubleSpinBox* rotationField() const { return rotation_; }
    QDoubleSpinBox* lumensField() const { return lumens_; }
    LuminairePolarPlot* polarPlot() const { return polar_; }
    // The circuit power in W (circuit_watts); empty: not given (a luminaire: its file's power,
    // shown in grey). Counts when the field is left or Enter is pressed.
    QLineEdit* circuitWattsField() const { return circuit_; }
    // Point, spot, luminaire: the light's own maintenance factor, or the scene's (README,
    // "Maintained values"); one undo step per edit.
    MaintenanceFactorEdit* maintenanceField() const { return maintenance_; }

private:
    enum class Field { Position, Tilt, Azimuth, Output, OutputUnit, Illuminance, Colour, Power, Cone, Falloff, Rotation, Lumens, Maintenance };
    std::array<QDoubleSpinBox*, 3> makeTriple(Field field);
    QDoubleSpinBox* makeSpin(Field field, double lo, double hi, int decimals);
    void refresh() override;
    void apply(Field field, const void* sender);
    void renameLight();
    void regroupLight();
    void applyCircuitWatts();

    QLabel *type_, *outputOther_, *file_, *sunNote_;
    QWidget *positionRow_, *tiltRow_, *azimuthRow_, *outputRow_, *illuminanceRow_, *colourRow_, *powerRow_;
    QWidget *coneRow_, *falloffRow_, *fileRow_, *rotationRow_, *lumensRow_, *polarRow_, *circuitRow_, *maintenanceRow_;
    QLineEdit* name_;
    QLineEdit* group_;
    QLineEdit* circuit_;
    std::array<QDoubleSpinBox*, 3> position_{}, power_{};
    QDoubleSpinBox *tilt_, *azimuth_, *output_, *illuminance_, *cone_, *falloff_, *rotation_, *lumens_;
    QComboBox* outputUnit_;
    LightColourEdit* colour_;
    QToolButton* advanced_;
    LuminairePolarPlot* polar_;
    MaintenanceFactorEdit* maintenance_;
    int aimLight_ = -1;  // the light whose bearing the azimuth field shows
};

}  // namespace lucerna
