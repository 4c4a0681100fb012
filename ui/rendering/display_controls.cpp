#include "ui/rendering/display_controls.h"

#include "render/display/false_colour.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace lucerna {

namespace {
enum Mode { Linear, Filmic, FalseColour, FalseColourLux };
// The white balance's choices after D65 and the lights: the usual lamp colours and daylight's.
constexpr int kWhiteTemperaturesK[] = {2700, 3000, 3500, 4000, 5000, 6500};
enum WhiteItem { WhiteD65, WhiteLights, WhiteFirstTemperature };

int whiteItem(const WhiteBalance& w) {
    if (w.reference == WhiteReference::DominantLights) return WhiteLights;
    if (w.reference == WhiteReference::Temperature)
        for (int i = 0; i < int(std::size(kWhiteTemperaturesK)); ++i)
            if (std::abs(w.kelvin - kWhiteTemperaturesK[i]) < 0.5) return WhiteFirstTemperature + i;
    return WhiteD65;
}

WhiteBalance whiteOfItem(int item) {
    WhiteBalance w;
    if (item == WhiteLights) w.reference = WhiteReference::DominantLights;
    if (item >= WhiteFirstTemperature && item < WhiteFirstTemperature + int(std::size(kWhiteTemperaturesK))) {
        w.reference = WhiteReference::Temperature;
        w.kelvin = kWhiteTemperaturesK[item - WhiteFirstTemperature];
    }
    return w;
}
}  // namespace

DisplayControls::DisplayControls(QWidget* parent) : QWidget(parent) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    exposure_ = new QDoubleSpinBox(this);
    exposure_->setObjectName("exposure");
    exposure_->setRange(-16, 16);
    exposure_->setSingleStep(0.5);
    exposure_->setDecimals(1);
    exposure_->setSuffix(tr(" stops"));
    exposure_->setToolTip(tr("Exposure: each stop doubles the displayed radiance"));
    mode_ = new QComboBox(this);
    mode_->setObjectName("toneMapping");
    mode_->addItems({tr("Linear sRGB"), tr("Filmic"), tr("False colour cd/m\u00b2"), tr("False colour lx")});
    mode_->setItemData(FalseColourLux,
                       tr("Illuminance at the surface each pixel sees: the illuminance layer where the image has one, "
                          "else pi x luminance / albedo (exact on matt surfaces under white light)"),
                       Qt::ToolTipRole);
    white_ = new QComboBox(this);
    white_->setObjectName("whiteBalance");
    white_->addItems({tr("White D65"), tr("White: the lights")});
    for (int k : kWhiteTemperaturesK) white_->addItem(tr("White %1 K").arg(k));
    white_->setToolTip(tr("White balance of the picture: the colour shown as white. D65 shows the values as rendered "
                          "(a 4000 K lamp looks warm); \"the lights\" takes the scene's lights' colour, weighted by their "
                          "flux. Never applied to false colour, lux figures or EXR files."));
    // The false-colour range; a log scale, so decades are the natural steps.
    const auto range = [this](const char* name, double value) {
        auto* spin = new QDoubleSpinBox(this);
        spin->setObjectName(name);
        spin->setRange(1e-4, 1e7);
        spin->setDecimals(4);
        spin->setValue(value);
        spin->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
        // A value as typed, not every prefix of it: "50" must not pass through 5 on its way.
        spin->setKeyboardTracking(false);
        spin->setSuffix(tr(" cd/m\u00b2"));
        return spin;
    };
    falseMin_ = range("falseMin", settings_.falseMin);
    falseMax_ = range("falseMax", settings_.falseMax);
    scale_ = new QComboBox(this);
    scale_->setObjectName("falseScale");
    for (LegendScale s : {LegendScale::Logarithmic, LegendScale::Linear, LegendScale::Bands})
        scale_->addItem(legendScaleName(s), int(s));
    scale_->setToolTip(tr("How the range maps to the colours: logarithmic, linear, or bands between round values"));
    layout->addWidget(new QLabel(tr("Exposure"), this));
    layout->addWidget(exposure_);
    layout->addWidget(mode_);
    layout->addWidget(white_);
    layout->addWidget(falseMin_);
    rangeTo_ = new QLabel(tr("to"), this);
    layout->addWidget(rangeTo_);
    layout->addWidget(falseMax_);
    layout->addWidget(scale_);
    layout->addStretch();
    setSettings(settings_);

    connect(exposure_, &QDoubleSpinBox::valueChanged, this, &DisplayControls::read);
    // With keyboard tracking off, valueChanged comes when the typing ends or an arrow steps.
    const auto rangeEdited = [this] {
        if (!(falseMax_->value() > falseMin_->value())) {
            const QString unit = settings_.quantity == FalseColourQuantity::Illuminance ? tr("lx") : tr("cd/m²");
            emit message(tr("False-colour range refused: the maximum (%1 %3) must be above the minimum (%2 %3)")
                             .arg(falseMax_->value())
                             .arg(falseMin_->value())
                             .arg(unit));
            const QSignalBlocker b1(falseMin_), b2(falseMax_);
            falseMin_->setValue(settings_.falseMin);
            falseMax_->setValue(settings_.falseMax);
            return;
        }
        read();
        emit rangeSetByUser();
    };
    connect(falseMin_, &QDoubleSpinBox::valueChanged, this, rangeEdited);
    connect(falseMax_, &QDoubleSpinBox::valueChanged, this, rangeEdited);
    connect(mode_, &QComboBox::currentIndexChanged, this, &DisplayControls::read);
    connect(scale_, &QComboBox::currentIndexChanged, this, &DisplayControls::read);
    connect(white_, &QComboBox::currentIndexChanged, this, &DisplayControls::read);
}

void DisplayControls::setSettings(const DisplaySettings& s) {
    // What the scene sets, no field shows: read() keeps it.
    settings_.illuminanceNote = s.illuminanceNote;
    settings_.lights = s.lights;
    {
        const QSignalBlocker b1(exposure_), b2(mode_), b3(falseMin_), b4(falseMax_), b5(scale_), b6(white_);
        scale_->setCurrentIndex(std::max(0, scale_->findData(int(s.scale))));
        exposure_->setValue(s.exposureStops);
        white_->setCurrentIndex(whiteItem(s.white));
        mode_->setCurrentIndex(!s.falseColour                                     ? (s.curve == ToneCurve::Filmic ? Filmic : Linear)
                               : s.quantity == FalseColourQuantity::Illuminance ? FalseColourLux
                                                                                : FalseColour);
        falseMin_->setValue(s.falseMin);
        falseMax_->setValue(s.falseMax);
    }
    read();
}

void DisplayControls::read() {
    DisplaySettings s;
    s.illuminanceNote = settings_.illuminanceNote;
    s.lights = settings_.lights;
    s.white = whiteOfItem(white_->currentIndex());
    s.exposureStops = float(exposure_->value());
    s.curve = mode_->currentIndex() == Filmic ? ToneCurve::Filmic : ToneCurve::LinearSrgb;
    s.falseColour = mode_->currentIndex() == FalseColour || mode_->currentIndex() == FalseColourLux;
    s.quantity = mode_->currentIndex() == FalseColourLux ? FalseColourQuantity::Illuminance
                                                         : FalseColourQuantity::Luminance;
    const QString unit = s.quantity == FalseColourQuantity::Illuminance ? tr(" lx") : tr(" cd/m\u00b2");
    falseMin_->setSuffix(unit);
    falseMax_->setSuffix(unit);
    // The fields hold a valid range (the edits refuse one the wrong way round); setSettings with
    // one would divide by zero or flip the legend, so a bad one keeps the previous.
    s.falseMin = falseMin_->value();
    s.falseMax = falseMax_->value();
    s.scale = LegendScale(scale_->currentData().toInt());
    if (!(s.falseMax > s.falseMin)) {
        s.falseMin = settings_.falseMin;
        s.falseMax = settings_.falseMax;
    }
    // Exposure does not apply to absolute luminance, and the range only to false colour.
    exposure_->setEnabled(!s.falseColour);
    white_->setVisible(!s.falseColour);
    falseMin_->setVisible(s.falseColour);
    falseMax_->setVisible(s.falseColour);
    rangeTo_->setVisible(s.falseColour);
    scale_->setVisible(s.falseColour);
    if (s == settings_) return;
    settings_ = s;
    emit settingsChanged(settings_);
}

}  // namespace lucerna
