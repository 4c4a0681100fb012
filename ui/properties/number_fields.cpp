#include "ui/properties/number_fields.h"

#include <QDoubleSpinBox>
#include <QLocale>

namespace lucerna {

QDoubleSpinBox* makeNumberField(QWidget* parent, const QString& name, double value, double lo, double hi,
                                const QString& suffix, int decimals, double step) {
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(name);
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setSingleStep(step);
    box->setValue(value);
    box->setSuffix(suffix);
    return box;
}

double sceneValue(const QDoubleSpinBox* box, std::optional<double> original, double scale) {
    if (original && box->value() == QString::number(*original * scale, 'f', box->decimals()).toDouble())
        return *original;
    return box->value() / scale;
}

std::optional<double> typedNumber(const QString& text) {
    bool ok = false;
    double x = QLocale::c().toDouble(text, &ok);
    if (!ok) x = QLocale().toDouble(text, &ok);
    return ok ? std::optional<double>(x) : std::nullopt;
}

}  // namespace lucerna
