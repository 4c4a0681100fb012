#pragma once
// The property panel of an object: its name, its material (chosen among the scene's), what its
// mesh is, its size in metres, and its transform as SPEC.md applies it: scale, then a rotation
// about an axis by degrees, then a translation in the scene's unit (meters_per_unit names it).
// Every change is an EditObjectCommand carrying the recomputed world mesh, so the preview and
// the converging render see the moved object; a field's arrow steps merge into one undo step.
// A transform given as a matrix is shown as such and not edited here. "Opening" marks the object
// as a daylight portal (Object::portal): a hole the light comes in through, not a surface.

#include "ui/properties/item_properties.h"

#include <array>
#include <memory>
#include <string>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace lucerna {

class ObjectProperties : public ItemProperties {
    Q_OBJECT
public:
    explicit ObjectProperties(Document* doc, QWidget* parent = nullptr);

    // -1: no object (the panel hides its fields).
    void setObject(int index) { select(index); }
    int object() const { return index_; }

    QLineEdit* nameField() const { return name_; }
    QComboBox* materialField() const { return material_; }
    const std::array<QDoubleSpinBox*, 3>& translateFields() const { return translate_; }
    QDoubleSpinBox* angleField() const { return angle_; }
    const std::array<QDoubleSpinBox*, 3>& scaleFields() const { return scale_; }
    QLabel* sizeLabel() const { return size_; }
    QCheckBox* portalField() const { return portal_; }

signals:
    // The object's material was reassigned (the material panel follows).
    void materialAssigned(int materialIndex);

private:
    std::array<QDoubleSpinBox*, 3> makeTriple(double lo, double hi, int decimals);
    void refresh() override;
    void applyTransform(const void* source);
    void renameObject();
    void assignMaterial();
    void markPortal(bool portal);
    // `o` with its world mesh for its new transform. A mesh file is read once and kept while the
    // object is edited, so that the steps of a drag do not parse it again.
    Object withWorldMesh(const Scene& scene, Object o);

    QLineEdit* name_;
    QComboBox* material_;
    QCheckBox* portal_;
    QLabel *mesh_, *size_, *matrixNote_;
    QWidget *translateRow_, *axisRow_, *angleRow_, *scaleRow_;
    std::array<QDoubleSpinBox*, 3> translate_{}, axis_{}, scale_{};
    QDoubleSpinBox* angle_;
    std::string cachedPath_;  // absolute path of the mesh file in cachedMesh_
    std::shared_ptr<const TriangleMesh> cachedMesh_;
};

}  // namespace lucerna
