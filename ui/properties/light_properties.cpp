#include "ui/properties/light_properties.h"

#include "ui/properties/number_fields.h"
#include "core/photometry/light_output.h"
#include "core/number_format.h"
#include "core/photometry/luminaire.h"
#include "core/scene/aim_angles.h"
#include "core/scene/scene_geometry.h"
#include "ui/properties/colour_edit.h"
#include "ui/commands/light_commands.h"
#include "ui/properties/light_colour_edit.h"
#include "ui/properties/luminaire_polar_plot.h"
#include "ui/scene_panels/maintenance_factor_edit.h"
#include "ui/viewport/viewport.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

namespace lucerna {

namespace {
constexpr int kLumens = 0, kCandela = 1;  // the output unit list

// The colour field's colour with the edited part taken from the field: the whole colour when it
// was picked, else only the channel typed (the others show rounded values, never written back).
Rgbd editedColour(const LightColourEdit* edit, const void* sender, Rgbd base) {
    const ColourEdit* c = edit->colourField();
    if (sender == c->swatch() || sender == edit->modeField()) return c->value();
    for (int i = 0; i < 3; ++i)
        if (sender == c->channel(i)) base[i] = c->channel(i)->value();
    return base;
}

// Straight down or up (to the fields' 0.01 degrees): no bearing to show or keep.
bool verticalAim(const AimAngles& aim) { return aim.tiltDeg < 0.005 || aim.tiltDeg > 179.995; }

// The colour a light's colour field shows: the temperature's, or the colour's, brightest channel 1.
Rgbd shownColour(std::optional<double> temperatureK, std::optional<Rgbd> colour) {
    if (temperatureK) return chromaticity(blackbodyColour(*temperatureK));
    return chromaticity(colour.value_or(Rgbd(1, 1, 1)));
}
}  // namespace

LightProperties::LightProperties(Document* doc, QWidget* parent)
    : ItemProperties(doc, tr("Select a light in the outliner or the viewport."), parent) {
    name_ = new QLineEdit(fields_);
    name_->setObjectName("lightName");
    type_ = new QLabel(fields_);
    addPropertyRow(rows_, tr("Name"), {name_});
    addPropertyRow(rows_, tr("Type"), {type_});
    group_ = new QLineEdit(fields_);
    group_->setObjectName("lightGroup");
    group_->setPlaceholderText(tr("none"));
    group_->setToolTip(tr("The light's group (the outliner shows it under the group's node); empty: none"));
    addPropertyRow(rows_, tr("Group"), {group_});
    position_ = makeTriple(Field::Position);
    positionRow_ = addTripleRow(rows_, tr("Position"), {position_[0], position_[1], position_[2]});
    rowLabel(positionRow_)->setObjectName("positionLabel");
    // The aim (core/scene/aim_angles.h).
    tilt_ = makeSpin(Field::Tilt, 0, 180, 2);
    tilt_->setSuffix(QStringLiteral(" °"));
    tilt_->setObjectName("lightTilt");
    tilt_->setToolTip(tr("Degrees from straight down: 0 hangs straight down, 90 is horizontal, 180 points up"));
    tiltRow_ = addPropertyRow(rows_, tr("Tilt"), {tilt_});
    azimuth_ = makeSpin(Field::Azimuth, 0, 360, 2);
    azimuth_->setSuffix(QStringLiteral(" °"));
    azimuth_->setWrapping(true);
    azimuth_->setObjectName("lightAzimuth");
    azimuth_->setToolTip(tr("The way the light leans, in degrees clockwise from the site's north seen from above "
                            "(0 north, 90 east, 180 south, 270 west; north is -z unless the Daylight panel's site "
                            "says otherwise). Nothing to turn while the tilt is 0 or 180."));
    azimuthRow_ = addPropertyRow(rows_, tr("Azimuth"), {azimuth_});

    // Luminaire.
    file_ = makeWrappingLabel(fields_, "luminaireFile");
    fileRow_ = addPropertyRow(rows_, tr("Photometry"), {file_});
    rotation_ = makeSpin(Field::Rotation, -360, 360, 2);
    rotation_->setSuffix(QStringLiteral(" °"));
    rotation_->setObjectName("luminaireRotation");
    rotation_->setToolTip(tr("The luminaire turned about its own axis (its C0 plane), in degrees"));
    rotationRow_ = addPropertyRow(rows_, tr("Rotation"), {rotation_});
    // Point and spot: lumens or candela.
    output_ = makeSpin(Field::Output, 0, 1e9, 1);
    output_->setObjectName("lightOutput");
    outputUnit_ = new QComboBox(fields_);
    outputUnit_->setObjectName("lightOutputUnit");
    outputUnit_->addItem(tr("lm"));
    outputUnit_->addItem(tr("cd"));
    outputUnit_->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
    connect(outputUnit_, &QComboBox::activated, this, [this] {
        apply(Field::OutputUnit, outputUnit_);
        merge_.finish();
    });
    outputRow_ = addPropertyRow(rows_, tr("Luminous flux"), {output_, outputUnit_});
    static_cast<QHBoxLayout*>(outputRow_->layout())->setStretchFactor(outputUnit_, 0);
    outputOther_ = new QLabel(fields_);
    outputOther_->setObjectName("lightOutputOther");
    rows_->addWidget(outputOther_);
    outputOther_->setIndent(114);
    // Directional: illuminance on a surface facing the light.
    illuminance_ = makeSpin(Field::Illuminance, 0, 1e7, 1);
    illuminance_->setObjectName("lightIlluminance");
    illuminance_->setSuffix(QStringLiteral(" lx"));
    illuminanceRow_ = addPropertyRow(rows_, tr("Illuminance"), {illuminance_});
    lumens_ = makeSpin(Field::Lumens, 0, 1e9, 1);
    lumens_->setSuffix(QStringLiteral(" lm"));
    lumens_->setObjectName("luminaireLumens");
    lumensRow_ = addPropertyRow(rows_, tr("Flux"), {lumens_});
    colour_ = new LightColourEdit(fields_);
    colour_->setObjectName("lightColourEdit");
    connect(colour_, &LightColourEdit::edited, this, [this](const void* source) { apply(Field::Colour, source); });
    connect(colour_, &LightColourEdit::editingFinished, this, [this] { merge_.finish(); });
    colourRow_ = addStackedPropertyRow(rows_, tr("Colour"), {colour_});

    cone_ = makeSpin(Field::Cone, 0.1, 179.9, 2);
    cone_->setSuffix(QStringLiteral(" °"));
    cone_->setObjectName("lightCone");
    falloff_ = makeSpin(Field::Falloff, 0.1, 179.9, 2);
    falloff_->setSuffix(QStringLiteral(" °"));
    falloff_->setObjectName("lightFalloff");
    // The circuit power, for the lighting energy (README, "Energy").
    circuit_ = new QLineEdit(fields_);
    circuit_->setObjectName("lightCircuitWatts");
    circuit_->setClearButtonEnabled(true);
    circuit_->setToolTip(tr("The light's circuit power in W, for the lighting energy (LENI); empty: a luminaire's "
                            "file's power, or none"));
    auto* watts = new QLabel(tr("W"), fields_);
    circuitRow_ = addPropertyRow(rows_, tr("Circuit power"), {circuit_, watts});
    static_cast<QHBoxLayout*>(circuitRow_->layout())->setStretchFactor(watts, 0);
    connect(circuit_, &QLineEdit::editingFinished, this, &LightProperties::applyCircuitWatts);

    coneRow_ = addPropertyRow(rows_, tr("Cone half-angle"), {cone_});
    falloffRow_ = addPropertyRow(rows_, tr("Falloff start"), {falloff_});

    maintenance_ = new MaintenanceFactorEdit(MaintenanceFactorEdit::Absent::SceneFactor, fields_);
    maintenance_->setObjectName("lightMaintenance");
    connect(maintenance_, &MaintenanceFactorEdit::edited, this, [this](const void* source) { apply(Field::Maintenance, source); });
    connect(maintenance_, &MaintenanceFactorEdit::editingFinished, this, [this] { merge_.finish(); });
    maintenanceRow_ = addStackedPropertyRow(rows_, tr("Maintenance"), {maintenance_});

    sunNote_ = makeWrappingLabel(fields_, "lightSunNote",
                                 tr("The sun's illuminance, disc, date and time are in the Daylight panel."));
    rows_->addWidget(sunNote_);

    polar_ = new LuminairePolarPlot(fields_);
    polar_->setObjectName("luminairePolarPlot");
    rows_->addWidget(polar_);
    polarRow_ = polar_;

    // The advanced view: the radiometric values the renderers use.
    advanced_ = new QToolButton(fields_);
    advanced_->setObjectName("lightAdvanced");
    advanced_->setText(tr("Radiometric values"));
    advanced_->setCheckable(true);
    advanced_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    advanced_->setArrowType(Qt::RightArrow);
    advanced_->setAutoRaise(true);
    rows_->addWidget(advanced_);
    power_ = makeTriple(Field::Power);
    powerRow_ = addTripleRow(rows_, tr("Intensity"), {power_[0], power_[1], power_[2]},
                             {QStringLiteral("R"), QStringLiteral("G"), QStringLiteral("B")});
    rowLabel(powerRow_)->setObjectName("powerLabel");
    connect(advanced_, &QToolButton::toggled, this, [this](bool on) {
        advanced_->setArrowType(on ? Qt::DownArrow : Qt::RightArrow);
        refresh();
    });
    rows_->addStretch(1);
    for (int i = 0; i < 3; ++i) {
        position_[size_t(i)]->setObjectName(QStringLiteral("lightPosition%1").arg(i));
        power_[size_t(i)]->setObjectName(QStringLiteral("lightPower%1").arg(i));
        power_[size_t(i)]->setRange(0, 1e12);
        power_[size_t(i)]->setDecimals(4);
    }
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(empty_);
    layout->addWidget(fields_);
    layout->addStretch(1);

    connect(name_, &QLineEdit::editingFinished, this, &LightProperties::renameLight);
    connect(group_, &QLineEdit::editingFinished, this, &LightProperties::regroupLight);
    connect(doc_, &Document::lightChanged, this, [this](int i) {
        if (i == index_) refresh();
    });
    connect(doc_, &Document::structureChanged, this, &LightProperties::refresh);
    connect(doc_, &Document::projectChanged, this, &LightProperties::refresh);  // the scene's factor
    refresh();
}

QDoubleSpinBox* LightProperties::makeSpin(Field field, double lo, double hi, int decimals) {
    return ItemProperties::makeSpin(lo, hi, decimals, [this, field](QDoubleSpinBox* spin) { apply(field, spin); });
}

std::array<QDoubleSpinBox*, 3> LightProperties::makeTriple(Field field) {
    std::array<QDoubleSpinBox*, 3> spins{};
    for (auto& s : spins) s = makeSpin(field, -1e9, 1e9, 2);
    return spins;
}

void LightProperties::refresh() {
    const Scene& scene = doc_->scene();
    if (!showsItem(scene.lights.size())) return;
    const Light& l = scene.lights[size_t(index_)];
    const auto quiet = quietFields();

    if (!name_->hasFocus() || name_->text().isEmpty()) name_->setText(QString::fromStdString(l.name));
    type_->setText(lightTypeName(l.type));
    if (!group_->hasFocus()) group_->setText(QString::fromStdString(l.group));
    const bool directional = l.type == LightType::Directional;
    const bool spot = l.type == LightType::Spot;
    const bool luminaire = l.type == LightType::Luminaire;
    const bool pointOrSpot = l.type == LightType::Point || spot;
    const bool sun = l.type == LightType::Sun;
    positionRow_->setVisible(!directional && !sun);
    const bool aimed = l.type != LightType::Point && !(sun && l.sun && l.sun->time);
    tiltRow_->setVisible(aimed);
    azimuthRow_->setVisible(aimed);
    colourRow_->setVisible(!sun);
    sunNote_->setVisible(sun);
    rowLabel(positionRow_)->setText(tr("Position (%1)").arg(lengthUnit(scene)));
    for (int i = 0; i < 3; ++i) position_[size_t(i)]->setValue(l.position[i]);
    const AimAngles aim = aimAngles(l.direction, horizontalNorth(scene));
    tilt_->setValue(aim.tiltDeg);
    // Straight down or up has no bearing: the field keeps the one shown for this light, for the
    // next tilt (another light's starts from north).
    if (!verticalAim(aim)) azimuth_->setValue(aim.azimuthDeg);
    else if (aimLight_ != index_) azimuth_->setValue(0);
    aimLight_ = index_;

    outputRow_->setVisible(pointOrSpot);
    outputOther_->setVisible(pointOrSpot);
    illuminanceRow_->setVisible(directional);
    coneRow_->setVisible(spot);
    falloffRow_->setVisible(spot);
    fileRow_->setVisible(luminaire);
    rotationRow_->setVisible(luminaire);
    lumensRow_->setVisible(luminaire);
    polarRow_->setVisible(luminaire);
    // A sun, a sky or a directional light takes no maintenance factor.
    maintenanceRow_->setVisible(pointOrSpot || luminaire);
    maintenance_->setSceneFactor(scene.maintenance ? std::optional(scene.maintenance->factor()) : std::nullopt);
    maintenance_->setValue(l.maintenance);
    circuitRow_->setVisible(pointOrSpot || luminaire);
    if (pointOrSpot || luminaire) {
        const std::optional<double> fromFile = l.luminaire && l.luminaire->distribution
                                                   ? l.luminaire->distribution->inputWatts
                                                   : std::nullopt;
        circuit_->setPlaceholderText(fromFile ? tr("%1 (the file's)").arg(QString::fromStdString(shortestNumber(*fromFile)))
                                              : tr("not stated"));
        if (!circuit_->hasFocus())
            circuit_->setText(l.circuitWatts ? QString::fromStdString(shortestNumber(*l.circuitWatts)) : QString());
    }
    // A luminaire's output is its file's distribution: no radiometric view of it.
    advanced_->setVisible(!luminaire && !sun);
    powerRow_->setVisible(!luminaire && !sun && advanced_->isChecked());
    colour_->setColourOnly(directional);  // the scene format has no temperature for a sun

    if (pointOrSpot) {
        const PhotometricSpec spec = photometricOf(l);
        const bool lumens = spec.quantity == PhotometricSpec::Quantity::Lumens;
        outputUnit_->setCurrentIndex(lumens ? kLumens : kCandela);
        rowLabel(outputRow_)->setText(lumens ? tr("Luminous flux") : tr("Intensity"));
        output_->setValue(spec.value);
        outputOther_->setText(lumens ? tr("%1 cd on axis").arg(luminousIntensityCd(l), 0, 'f', 1)
                                     : tr("%1 lm in all").arg(luminousFluxLm(l), 0, 'f', 1));
        colour_->setValue(spec.temperatureK, shownColour(spec.temperatureK, spec.colour));
        cone_->setValue(l.coneAngleDeg);
        falloff_->setValue(l.falloffStartDeg.value_or(l.coneAngleDeg));
    }
    if (directional) {
        illuminance_->setValue(illuminanceLx(l));
        colour_->setValue(std::nullopt, chromaticity(l.irradiance));
    }
    if (luminaire && l.luminaire) {
        const LuminaireSpec& spec = *l.luminaire;
        QString file = QString::fromStdString(spec.file);
        if (spec.distribution && !spec.distribution->name.empty())
            file += QStringLiteral(" (%1)").arg(QString::fromStdString(spec.distribution->name));
        file_->setText(spec.distribution ? file : tr("%1 (not loaded)").arg(file));
        rotation_->setValue(spec.rotationDeg.value_or(0.0));
        const double flux = luminaireFlux(l);
        lumens_->setValue(flux);
        lumens_->setEnabled(spec.distribution != nullptr);
        colour_->setValue(spec.temperatureK, shownColour(spec.temperatureK, spec.colour));
        // The scene's candela per candela of the file: 683 x the luminance of the radiant scale.
        polar_->setDistribution(spec.distribution, kLumensPerWatt * luminance(luminaireRadiantScale(l)), flux);
    }
    rowLabel(powerRow_)->setText(directional ? tr("Irradiance (W/m²)") : tr("Intensity (W/sr)"));
    const Rgbd& power = directional ? l.irradiance : l.intensity;
    for (int i = 0; i < 3; ++i) power_[size_t(i)]->setValue(power[i]);
}

void LightProperties::apply(Field field, const void* sender) {
    const Scene& scene = doc_->scene();
    if (index_ < 0 || index_ >= int(scene.lights.size())) return;
    const Light& old = scene.lights[size_t(index_)];
    Light l = old;
    QString what;
    // Only the component that changed: the other fields show values rounded to their decimals,
    // which must not be written back.
    const auto take = [sender](const std::array<QDoubleSpinBox*, 3>& fields, V3d value) {
        for (int i = 0; i < 3; ++i)
            if (fields[size_t(i)] == sender) value[i] = fields[size_t(i)]->value();
        return value;
    };
    const bool pointOrSpot = l.type == LightType::Point || l.type == LightType::Spot;
    switch (field) {
    case Field::Position:
        l.position = take(position_, l.position);
        what = tr("Move %1");
        break;
    case Field::Tilt:
    case Field::Azimuth: {
        // The angle typed, and the other one exactly as the light has it (the field shows it
        // rounded), but for a vertical light's bearing, which only the field holds.
        const V3d north = horizontalNorth(scene);
        AimAngles aim = aimAngles(l.direction, north);
        if (field == Field::Tilt) {
            aim.tiltDeg = tilt_->value();
            if (verticalAim(aimAngles(l.direction, north))) aim.azimuthDeg = azimuth_->value();
        } else {
            aim.azimuthDeg = azimuth_->value();
        }
        const V3d d = aimDirection(aim, north);
        // A vertical light turned about the vertical stays as it is.
        if (verticalAim(aimAngles(l.direction, north)) && verticalAim(aim)) return;
        l.direction = d;
        what = tr("Aim %1");
        break;
    }
    case Field::Output: {
        if (!pointOrSpot) return;
        PhotometricSpec spec = photometricOf(l);
        spec.value = output_->value();
        l = withPhotometric(l, spec);
        what = spec.quantity == PhotometricSpec::Quantity::Lumens ? tr("Change flux of %1") : tr("Change intensity of %1");
        break;
    }
    case Field::OutputUnit: {
        if (!pointOrSpot) return;
        PhotometricSpec spec = photometricOf(l);
        const bool lumens = outputUnit_->currentIndex() == kLumens;
        spec.quantity = lumens ? PhotometricSpec::Quantity::Lumens : PhotometricSpec::Quantity::Candela;
        spec.value = lumens ? luminousFluxLm(l) : luminousIntensityCd(l);
        l = withPhotometric(l, spec);
        what = lumens ? tr("Give %1 in lumens") : tr("Give %1 in candela");
        break;
    }
    case Field::Illuminance:
        if (l.type != LightType::Directional) return;
        l = withIlluminance(l, illuminance_->value());
        what = tr("Change illuminance of %1");
        break;
    case Field::Colour: {
        std::optional<double> kelvin;
        std::optional<Rgbd> colour;
        if (colour_->usesTemperature()) {
            kelvin = colour_->temperatureK();
        } else {
            const Rgbd before = l.type == LightType::Directional ? chromaticity(l.irradiance)
                                : l.luminaire ? shownColour(l.luminaire->temperatureK, l.luminaire->colour)
                                              : shownColour(photometricOf(l).temperatureK, photometricOf(l).colour);
            colour = editedColour(colour_, sender, before);
            // A black light colour has no hue to keep the flux with: refused.
            if (!(luminance(*colour) > 0)) {
                refresh();
                return;
            }
        }
        if (l.type == LightType::Directional) {
            if (!colour) return;
            l = withIrradianceColour(l, *colour);
        } else if (l.luminaire) {
            l.luminaire->temperatureK = kelvin;
            l.luminaire->colour = colour;
        } else {
            PhotometricSpec spec = photometricOf(l);
            spec.temperatureK = kelvin;
            spec.colour = colour;
            l = withPhotometric(l, spec);
        }
        what = tr("Change colour of %1");
        break;
    }
    case Field::Power: {
        if (l.type == LightType::Directional) l.irradiance = take(power_, l.irradiance);
        else l = withRadiantIntensity(l, take(power_, l.intensity));
        what = tr("Change power of %1");
        break;
    }
    case Field::Cone: {
        // SPEC.md: falloff_start is at most cone_angle.
        std::optional<double> falloff = l.falloffStartDeg;
        if (falloff && *falloff > cone_->value()) falloff = cone_->value();
        l = withSpotAngles(l, cone_->value(), falloff);
        what = tr("Change cone of %1");
        break;
    }
    case Field::Falloff:
        l = withSpotAngles(l, l.coneAngleDeg, std::min(falloff_->value(), l.coneAngleDeg));
        what = tr("Change falloff of %1");
        break;
    case Field::Rotation:
        if (!l.luminaire) return;
        l.luminaire->rotationDeg = rotation_->value();
        what = tr("Turn %1");
        break;
    case Field::Maintenance:
        if (!pointOrSpot && !l.luminaire) return;
        l.maintenance = maintenance_->value();
        what = tr("Change maintenance factor of %1");
        break;
    case Field::Lumens:
        if (!l.luminaire) return;
        // The flux shown is after the tilt multiplier; "lumens" is the flux before it.
        if (const double tilt = l.luminaire->distribution ? l.luminaire->distribution->tiltMultiplier(
                                    luminaireTiltDeg(l.direction)) : 0.0; tilt > 0)
            l.luminaire->lumens = lumens_->value() / tilt;
        what = tr("Change flux of %1");
        break;
    }
    if (l == old) {
        refresh();  // e.g. a unit switched back: the fields show the light as it is
        return;
    }
    const int key = merge_.keyFor(sender);
    doc_->undoStack()->push(new EditLightCommand(doc_, index_, l, key, what.arg(QString::fromStdString(l.name))));
}

void LightProperties::renameLight() {
    if (index_ >= 0 && index_ < int(doc_->scene().lights.size()))
        rename<EditLightCommand>(name_, doc_->light(index_));
}

void LightProperties::applyCircuitWatts() {
    const Scene& scene = doc_->scene();
    if (index_ < 0 || index_ >= int(scene.lights.size())) return;
    Light l = scene.lights[size_t(index_)];
    const QString text = circuit_->text().trimmed();
    std::optional<double> watts;
    if (!text.isEmpty()) {
        watts = typedNumber(text);
        // The scene file's range (core/scene/light_keys.cpp): refused, the field shows the light.
        if (!watts || !(*watts >= 0 && *watts <= 1e6)) {
            circuit_->setText(l.circuitWatts ? QString::fromStdString(shortestNumber(*l.circuitWatts)) : QString());
            return;
        }
    }
    if (watts == l.circuitWatts) return;
    l.circuitWatts = watts;
    const QString name = QString::fromStdString(l.name);
    doc_->undoStack()->push(new EditLightCommand(doc_, index_, l, 0,
                                                 watts ? tr("Change circuit power of %1").arg(name)
                                                       : tr("Clear circuit power of %1").arg(name)));
}

void LightProperties::regroupLight() {
    const Scene& scene = doc_->scene();
    if (index_ < 0 || index_ >= int(scene.lights.size())) return;
    Light l = scene.lights[size_t(index_)];
    const std::string group = group_->text().trimmed().toStdString();
    if (group == l.group) return;
    const QString name = QString::fromStdString(l.name);
    const QString text = group.empty() ? tr("Ungroup %1").arg(name) : tr("Group %1 in %2").arg(name, QString::fromStdString(group));
    l.group = group;
    doc_->undoStack()->push(new EditLightCommand(doc_, index_, l, 0, text));
}

}  // namespace lucerna
