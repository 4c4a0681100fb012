#pragma once
// The property panel of the selected light: name, position, direction, intensity or irradiance
// and the spot's cone, as typed fields with units (lengths in the scene's unit from
// meters_per_unit; W/sr, W/m^2, degrees); for a luminaire its file, rotation about the nadir and
// total flux in lumens instead of the intensity. Every change is an EditLightCommand: the arrow steps
// of one field merge into one undo step until the field's editing finishes.

#include "ui/document.h"

#include <QWidget>

#include <array>
#include <initializer_list>

class QDoubleSpinBox;
class QVBoxLayout;
class QLabel;
class QLineEdit;

namespace lucerna {

class LightProperties : public QWidget {
    Q_OBJECT
public:
    explicit LightProperties(Document* doc, QWidget* parent = nullptr);

    // -1: no light (the panel says so).
    void setLight(int index);
    int light() const { return index_; }

    // The fields, for tests and for focus.
    QLineEdit* nameField() const { return name_; }
    const std::array<QDoubleSpinBox*, 3>& positionFields() const { return position_; }
    const std::array<QDoubleSpinBox*, 3>& directionFields() const { return direction_; }
    const std::array<QDoubleSpinBox*, 3>& powerFields() const { return power_; }
    QDoubleSpinBox* coneField() const { return cone_; }
    QDoubleSpinBox* falloffField() const { return falloff_; }
    QDoubleSpinBox* rotationField() const { return rotation_; }
    QDoubleSpinBox* lumensField() const { return lumens_; }

private:
    enum class Field { Position, Direction, Power, Cone, Falloff, Rotation, Lumens };
    QWidget* addRow(const QString& label, std::initializer_list<QWidget*> fields);
    std::array<QDoubleSpinBox*, 3> makeTriple(QWidget*& row, Field field, const QString& label);
    QDoubleSpinBox* makeSpin(Field field);
    void refresh();
    void apply(Field field, QObject* sender);
    void renameLight();

    Document* doc_;
    int index_ = -1;
    QLabel *empty_, *type_, *positionLabel_ = nullptr, *powerLabel_ = nullptr;
    QWidget *fields_, *positionRow_ = nullptr, *directionRow_ = nullptr, *powerRow_ = nullptr;
    QWidget *coneRow_ = nullptr, *falloffRow_ = nullptr;
    QWidget *fileRow_ = nullptr, *rotationRow_ = nullptr, *lumensRow_ = nullptr;
    QLabel* file_ = nullptr;
    QLabel* directionLabel_ = nullptr;
    QVBoxLayout* rows_ = nullptr;
    QLineEdit* name_;
    std::array<QDoubleSpinBox*, 3> position_{}, direction_{}, power_{};
    QDoubleSpinBox *cone_, *falloff_, *rotation_, *lumens_;
    // Merging: edits of the same field with the same key fold into one command.
    QObject* lastField_ = nullptr;
    int mergeKey_ = 0;
};

}  // namespace lucerna
