#include "ui/properties/light_colour_edit.h"

#include "ui/disconnect_children.h"
#include "ui/properties/colour_edit.h"
#include "ui/properties/property_rows.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QVBoxLayout>
#include <QSignalBlocker>

namespace lucerna {

LightColourEdit::~LightColourEdit() { disconnectChildren(this); }

LightColourEdit::LightColourEdit(QWidget* parent) : QWidget(parent) {
    // The mode beside the temperature; a colour's three channels on a line of their own, so that
    // the field fits a narrow dock.
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->setSpacing(2);
    auto* h = new QHBoxLayout;
    mode_ = new QComboBox(this);
    mode_->setObjectName("lightColourMode");
    mode_->addItem(tr("Temperature"));
    mode_->addItem(tr("Colour"));
    mode_->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
    // README: blackbody temperatures from 1000 to 40000 K.
    temperature_ = makePropertySpin(this, 1000, 40000, 0);
    temperature_->setObjectName("lightTemperature");
    temperature_->setSuffix(QStringLiteral(" K"));
    temperature_->setSingleStep(100);
    temperature_->setValue(3000);
    colour_ = new ColourEdit(1.0, this);
    colour_->setObjectName("lightColour");
    h->addWidget(mode_);
    h->addWidget(temperature_, 1);
    v->addLayout(h);
    v->addWidget(colour_);
    connect(mode_, &QComboBox::activated, this, [this] {
        showMode();
        emit edited(mode_);
        emit editingFinished();  // a change of mode is a step of its own
    });
    connect(temperature_, &QDoubleSpinBox::valueChanged, this, [this] { emit edited(temperature_); });
    connect(temperature_, &QDoubleSpinBox::editingFinished, this, &LightColourEdit::editingFinished);
    connect(colour_, &ColourEdit::edited, this, &LightColourEdit::edited);
    connect(colour_, &ColourEdit::editingFinished, this, &LightColourEdit::editingFinished);
    showMode();
}

void LightColourEdit::setValue(std::optional<double> temperatureK, const Rgbd& colour) {
    const QSignalBlocker b1(mode_), b2(temperature_);
    mode_->setCurrentIndex(temperatureK ? 0 : 1);
    if (temperatureK) temperature_->setValue(*temperatureK);
    // Switching to a colour starts from the temperature's colour, so the light does not jump.
    colour_->setValue(colour);
    showMode();
}

void LightColourEdit::setColourOnly(bool only) {
    mode_->setVisible(!only);
    if (only) {
        const QSignalBlocker b(mode_);
        mode_->setCurrentIndex(1);
    }
    showMode();
}

bool LightColourEdit::usesTemperature() const { return mode_->currentIndex() == 0; }
double LightColourEdit::temperatureK() const { return temperature_->value(); }

void LightColourEdit::showMode() {
    temperature_->setVisible(usesTemperature());
    colour_->setVisible(!usesTemperature());
}

}  // namespace lucerna
