#pragma once
// A linear RGB colour as three typed channels and a swatch that opens a colour picker. The
// picker works in sRGB, as the screen shows colours; the value stays linear Rec.709 (SPEC.md).
// For a reflectance the channels are bounded to [0, 1]; for a radiance the picker chooses the
// hue and keeps the brightest channel's value, so that picking a colour does not change power.

#include "core/math.h"

#include <QColor>
#include <QWidget>

#include <array>

class QDoubleSpinBox;
class QToolButton;

namespace lucerna {

class ColourEdit : public QWidget {
    Q_OBJECT
public:
    // maxValue: the channels' upper bound (1 for reflectances).
    explicit ColourEdit(double maxValue, QWidget* parent = nullptr);
    ~ColourEdit() override;  // disconnects its children first (ui/disconnect_children.h)

    // Shows a value without emitting edited().
    void setValue(const Rgbd& value);
    Rgbd value() const;
    QDoubleSpinBox* channel(int c) const { return channels_[size_t(c)]; }
    QToolButton* swatch() const { return swatch_; }
    // What choosing `srgb` in the picker does (the dialog itself is modal; tests call this).
    void pick(const QColor& srgb);

signals:
    // The value changed by the user; `source` is the field that changed it (for undo merging).
    void edited(const void* source);
    void editingFinished();

private:
    void updateSwatch();

    double max_;
    std::array<QDoubleSpinBox*, 3> channels_{};
    QToolButton* swatch_;
};

// Linear value in [0, 1] to the sRGB-encoded one and back (IEC 61966-2-1).
double linearToSrgb(double v);
double srgbToLinear(double v);

}  // namespace lucerna
