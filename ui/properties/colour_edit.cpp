#include "ui/properties/colour_edit.h"

#include "ui/disconnect_children.h"
#include "ui/properties/property_rows.h"

#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QToolButton>

namespace lucerna {

double linearToSrgb(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

double srgbToLinear(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

ColourEdit::~ColourEdit() { disconnectChildren(this); }

ColourEdit::ColourEdit(double maxValue, QWidget* parent) : QWidget(parent), max_(maxValue) {
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(0, 0, 0, 0);
    const char* tips[3] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c) {
        QDoubleSpinBox* spin = makePropertySpin(this, 0.0, maxValue, 3);
        spin->setSingleStep(maxValue <= 1.0 ? 0.01 : 0.1);
        spin->setToolTip(tr(tips[c]));
        channels_[size_t(c)] = spin;
        h->addWidget(spin, 1);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [this, spin] {
            updateSwatch();
            emit edited(spin);
        });
        connect(spin, &QDoubleSpinBox::editingFinished, this, &ColourEdit::editingFinished);
    }
    swatch_ = new QToolButton(this);
    swatch_->setToolTip(tr("Choose a colour"));
    swatch_->setFixedSize(24, 22);
    h->addWidget(swatch_);
    connect(swatch_, &QToolButton::clicked, this, [this] {
        const Rgbd v = value();
        const double peak = std::max({v.x, v.y, v.z});
        const double s = peak > 1.0 ? 1.0 / peak : 1.0;
        const QColor start = QColor::fromRgbF(float(linearToSrgb(v.x * s)), float(linearToSrgb(v.y * s)),
                                              float(linearToSrgb(v.z * s)));
        const QColor chosen = QColorDialog::getColor(start, this, tr("Choose a colour"));
        if (chosen.isValid()) pick(chosen);
    });
    updateSwatch();
}

void ColourEdit::setValue(const Rgbd& value) {
    for (int c = 0; c < 3; ++c) {
        const QSignalBlocker block(channels_[size_t(c)]);
        channels_[size_t(c)]->setValue(value[c]);
    }
    updateSwatch();
}

Rgbd ColourEdit::value() const {
    return Rgbd(channels_[0]->value(), channels_[1]->value(), channels_[2]->value());
}

void ColourEdit::pick(const QColor& srgb) {
    Rgbd linear(srgbToLinear(srgb.redF()), srgbToLinear(srgb.greenF()), srgbToLinear(srgb.blueF()));
    if (max_ > 1.0) {
        // A radiance: the picked hue at the brightness the value had (1 when it was black).
        const Rgbd old = value();
        const double oldPeak = std::max({old.x, old.y, old.z}), newPeak = std::max({linear.x, linear.y, linear.z});
        if (newPeak > 0) linear *= (oldPeak > 0 ? oldPeak : 1.0) / newPeak;
    }
    setValue(linear);
    emit edited(swatch_);
    emit editingFinished();  // one pick, one undo step
}

void ColourEdit::updateSwatch() {
    const Rgbd v = value();
    const double peak = std::max({v.x, v.y, v.z});
    const double s = peak > 1.0 ? 1.0 / peak : 1.0;  // radiance: show the hue
    const QColor c = QColor::fromRgbF(float(linearToSrgb(v.x * s)), float(linearToSrgb(v.y * s)),
                                      float(linearToSrgb(v.z * s)));
    swatch_->setStyleSheet(QStringLiteral("QToolButton { background-color: %1; border: 1px solid palette(mid); }")
                               .arg(c.name()));
}

}  // namespace lucerna
