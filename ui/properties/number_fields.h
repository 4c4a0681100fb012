#pragma once
// Numeric fields the dialogs and panels share: a spin box made in one call, the scene value a
// field stands for, and a number as a person types it.

#include <QString>

#include <optional>

class QDoubleSpinBox;
class QWidget;

namespace lucerna {

// A spin box named `name` (tests find it by it) over [lo, hi] showing `value`.
QDoubleSpinBox* makeNumberField(QWidget* parent, const QString& name, double value, double lo, double hi,
                                const QString& suffix, int decimals, double step = 1);

// The scene's value of a field that shows it times `scale` (metres per scene unit for a length,
// 100 for a percentage): the value it was opened on while it still shows that, so that a dialog
// opened and accepted keeps every number to the last bit, else what was typed.
double sceneValue(const QDoubleSpinBox* box, std::optional<double> original, double scale);

// A number as typed: the C locale's, or the system's (a decimal comma); nothing for other text.
std::optional<double> typedNumber(const QString& text);

}  // namespace lucerna
