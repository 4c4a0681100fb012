#pragma once
// The display settings a user changes: exposure in stops, and how radiance becomes a picture
// (linear sRGB, the filmic curve, or false-colour luminance in cd/m^2 with its range).

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

private:
    void read();

    DisplaySettings settings_;
    QDoubleSpinBox *exposure_, *falseMin_, *falseMax_;
    QComboBox* mode_;
    QWidget* rangeTo_;  // the "to" between the range's ends
};

}  // namespace lucerna
