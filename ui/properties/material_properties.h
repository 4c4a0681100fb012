#pragma once
// The property panel of a material (the one selected in the outliner, or the selected object's):
// its type and that type's fields from SPEC.md section 1 with units: albedo, specular and
// reflectance as colours in [0, 1], roughness as a slider in (0, 1], the index of refraction,
// and an emitter's radiance in W sr^-1 m^-2 with its luminance in cd/m^2 (683 Y). Every change is
// an EditMaterialCommand; a slider drag or a field's arrow steps merge into one undo step.

#include "ui/properties/item_properties.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace lucerna {

class ColourEdit;

class MaterialProperties : public ItemProperties {
    Q_OBJECT
public:
    explicit MaterialProperties(Document* doc, QWidget* parent = nullptr);

    // -1: no material (the panel says so).
    void setMaterial(int index) { select(index); }
    int material() const { return index_; }

    // The fields, for tests.
    QComboBox* typeField() const { return type_; }
    ColourEdit* albedoField() const { return albedo_; }
    ColourEdit* specularField() const { return specular_; }
    ColourEdit* radianceField() const { return radiance_; }
    QSlider* roughnessSlider() const { return roughnessSlider_; }
    QDoubleSpinBox* roughnessField() const { return roughness_; }
    QDoubleSpinBox* iorField() const { return ior_; }
    QLabel* luminanceLabel() const { return luminance_; }

private:
    void refresh() override;
    // Pushes the edited material; `source` is the widget that changed (undo merging).
    void push(Material m, const void* source, const QString& what);
    void applyFields(const void* source);

    QLabel *name_, *luminance_;
    QComboBox* type_;
    ColourEdit *albedo_, *specular_, *reflectance_, *radiance_, *transmittance_;
    QSlider* roughnessSlider_;
    QDoubleSpinBox *roughness_, *ior_;
    QWidget *albedoRow_, *specularRow_, *roughnessRow_, *reflectanceRow_, *iorRow_, *radianceRow_, *luminanceRow_,
        *transmittanceRow_;
};

}  // namespace lucerna
