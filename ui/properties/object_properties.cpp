#include "ui/properties/object_properties.h"

#include "core/mesh/mesh_file.h"
#include "core/scene/scene_geometry.h"
#include "ui/commands/object_commands.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <limits>

namespace lucerna {

ObjectProperties::ObjectProperties(Document* doc, QWidget* parent) : ItemProperties(doc, {}, parent) {
    name_ = new QLineEdit(fields_);
    name_->setObjectName("objectName");
    material_ = new QComboBox(fields_);
    material_->setObjectName("objectMaterial");
    mesh_ = makeWrappingLabel(fields_, "objectMesh");
    size_ = new QLabel(fields_);
    size_->setObjectName("objectSize");
    addPropertyRow(rows_, tr("Object"), {name_});
    addPropertyRow(rows_, tr("Material"), {material_});
    portal_ = new QCheckBox(tr("Daylight portal: light passes through"), fields_);
    portal_->setObjectName("objectPortal");
    portal_->setToolTip(tr("An opening, not a surface: rays pass through the object untouched and daylight is sent "
                           "through it, as through an open door of a drawn room. Mark the quad that fills a window "
                           "or a door of an imported model."));
    addPropertyRow(rows_, tr("Opening"), {portal_});
    addPropertyRow(rows_, tr("Mesh"), {mesh_});
    addPropertyRow(rows_, tr("Size"), {size_});

    translate_ = makeTriple(-1e9, 1e9, 2);
    translateRow_ = addPropertyRow(rows_, tr("Translate"), {translate_[0], translate_[1], translate_[2]});
    axis_ = makeTriple(-1e6, 1e6, 4);
    for (QDoubleSpinBox* s : axis_) s->setSingleStep(0.1);
    axisRow_ = addPropertyRow(rows_, tr("Rotation axis"), {axis_[0], axis_[1], axis_[2]});
    angle_ = makeSpin(-360.0, 360.0, 2, [this](QDoubleSpinBox* spin) { applyTransform(spin); });
    angle_->setSuffix(QStringLiteral(" °"));
    angle_->setObjectName("objectAngle");
    angleRow_ = addPropertyRow(rows_, tr("Rotation angle"), {angle_});
    scale_ = makeTriple(-1e6, 1e6, 3);
    for (QDoubleSpinBox* s : scale_) s->setSingleStep(0.1);
    scaleRow_ = addPropertyRow(rows_, tr("Scale"), {scale_[0], scale_[1], scale_[2]});
    matrixNote_ = makeWrappingLabel(fields_, {}, tr("The transform is a matrix in the scene file; edit it there."));
    rows_->addWidget(matrixNote_);
    rows_->addStretch(1);  // rows packed at the top while hidden ones still count in the hint
    for (int i = 0; i < 3; ++i) {
        translate_[size_t(i)]->setObjectName(QStringLiteral("objectTranslate%1").arg(i));
        axis_[size_t(i)]->setObjectName(QStringLiteral("objectAxis%1").arg(i));
        scale_[size_t(i)]->setObjectName(QStringLiteral("objectScale%1").arg(i));
    }

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(fields_);

    connect(name_, &QLineEdit::editingFinished, this, &ObjectProperties::renameObject);
    connect(material_, &QComboBox::activated, this, &ObjectProperties::assignMaterial);
    connect(portal_, &QCheckBox::toggled, this, &ObjectProperties::markPortal);
    connect(doc_, &Document::changed, this, &ObjectProperties::refresh);
    refresh();
}

std::array<QDoubleSpinBox*, 3> ObjectProperties::makeTriple(double lo, double hi, int decimals) {
    std::array<QDoubleSpinBox*, 3> spins{};
    for (auto& s : spins) s = makeSpin(lo, hi, decimals, [this](QDoubleSpinBox* spin) { applyTransform(spin); });
    return spins;
}

void ObjectProperties::refresh() {
    const Scene& scene = doc_->scene();
    if (!showsItem(scene.objects.size())) return;
    const Object& o = scene.objects[size_t(index_)];
    const auto quiet = quietFields();

    if (!name_->hasFocus() || name_->text().isEmpty()) name_->setText(QString::fromStdString(o.name));
    material_->clear();
    for (const Material& m : scene.materials) material_->addItem(QString::fromStdString(m.name));
    material_->setCurrentIndex(scene.materialIndex(o.material));
    material_->setEnabled(!o.portal);  // an opening has no surface
    portal_->setChecked(o.portal);

    const size_t triangles = o.worldMesh ? o.worldMesh->triangles.size() : 0;
    const QString count = triangles == 1 ? tr("1 triangle") : tr("%1 triangles").arg(triangles);
    switch (o.mesh.kind) {
    case MeshSource::Kind::Inline: mesh_->setText(tr("inline, %1").arg(count)); break;
    case MeshSource::Kind::Quad: mesh_->setText(tr("quad")); break;
    case MeshSource::Kind::File:
        // The file's name; the path as the scene file holds it in the tooltip (it can be long).
        mesh_->setText(tr("%1, %2").arg(QFileInfo(QString::fromStdString(o.mesh.file)).fileName(), count));
        break;
    }
    mesh_->setToolTip(o.mesh.kind == MeshSource::Kind::File ? QString::fromStdString(o.mesh.file) : QString());
    // The size in metres whatever the scene's unit: what a designer checks an import against.
    QString size = tr("empty");
    if (o.worldMesh && !o.worldMesh->vertices.empty()) {
        V3d lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
        for (const V3d& v : o.worldMesh->vertices) {
            lo = V3d(std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z));
            hi = V3d(std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z));
        }
        const V3d d = (hi - lo) * scene.metersPerUnit;
        size = tr("%1 × %2 × %3 m").arg(d.x, 0, 'g', 4).arg(d.y, 0, 'g', 4).arg(d.z, 0, 'g', 4);
    }
    size_->setText(size);

    const Transform t = o.transform.value_or(Transform{});
    const bool editable = !t.isMatrix;
    for (QWidget* row : {translateRow_, axisRow_, angleRow_, scaleRow_}) row->setVisible(editable);
    matrixNote_->setVisible(!editable);
    rowLabel(translateRow_)->setText(tr("Translate (%1)").arg(lengthUnit(scene)));
    for (int i = 0; i < 3; ++i) {
        translate_[size_t(i)]->setValue(t.translate[i]);
        axis_[size_t(i)]->setValue(t.rotateAxis[i]);
        scale_[size_t(i)]->setValue(t.scale[i]);
    }
    angle_->setValue(t.rotateDeg);
}

void ObjectProperties::applyTransform(const void* source) {
    const Scene& scene = doc_->scene();
    if (index_ < 0 || index_ >= int(scene.objects.size())) return;
    Object o = scene.objects[size_t(index_)];
    Transform t = o.transform.value_or(Transform{});
    if (t.isMatrix) return;
    // Only the field that changed: the others show rounded values, which must not be written back.
    V3d translate = t.translate, axis = t.rotateAxis, scale = t.scale;
    bool scaled = false;
    for (int i = 0; i < 3; ++i) {
        if (source == translate_[size_t(i)]) translate[i] = translate_[size_t(i)]->value();
        if (source == axis_[size_t(i)]) axis[i] = axis_[size_t(i)]->value();
        if (source == scale_[size_t(i)]) {
            scale[i] = scale_[size_t(i)]->value();
            scaled = true;
        }
    }
    // SPEC.md: a non-zero rotation axis and scale. Refuse the edit and show the object as it is.
    if (axis == V3d(0, 0, 0) || scale.x == 0 || scale.y == 0 || scale.z == 0) {
        refresh();
        return;
    }
    t.translate = translate;
    t.scale = scale;
    if (scaled) t.uniformScale = scale.x == scale.y && scale.y == scale.z;
    if (source == angle_) t.rotateDeg = angle_->value();
    t.hasRotate = t.hasRotate || t.rotateDeg != 0 || axis != t.rotateAxis;
    t.rotateAxis = axis;
    if (o.transform && *o.transform == t) return;
    if (!o.transform && t == Transform{}) return;
    o.transform = t;
    try {
        o = withWorldMesh(scene, std::move(o));
    } catch (const std::exception&) {
        refresh();  // e.g. vertices beyond single precision: the edit is refused
        return;
    }
    const QString what = source == angle_ || std::find(axis_.begin(), axis_.end(), source) != axis_.end()
                             ? tr("Rotate %1")
                         : std::find(scale_.begin(), scale_.end(), source) != scale_.end() ? tr("Scale %1")
                                                                                            : tr("Move %1");
    const QString text = what.arg(QString::fromStdString(o.name));
    doc_->undoStack()->push(new EditObjectCommand(doc_, index_, std::move(o), merge_.keyFor(source), text));
}

Object ObjectProperties::withWorldMesh(const Scene& scene, Object o) {
    if (o.mesh.kind != MeshSource::Kind::File) return resolvedObject(scene, std::move(o));
    const std::string path =
        QDir(QString::fromStdString(scene.baseDir)).absoluteFilePath(QString::fromStdString(o.mesh.file)).toStdString();
    if (path != cachedPath_ || !cachedMesh_) {
        cachedMesh_ = std::make_shared<const TriangleMesh>(readMeshFile(path));
        cachedPath_ = path;
    }
    // The loader's own transform and checks, on the mesh as read, given inline.
    Object local = o;
    local.mesh.kind = MeshSource::Kind::Inline;
    local.mesh.inlineMesh = *cachedMesh_;
    local.mesh.file.clear();
    o.worldMesh = resolvedObject(scene, std::move(local)).worldMesh;
    return o;
}

void ObjectProperties::renameObject() {
    if (index_ >= 0 && index_ < int(doc_->scene().objects.size()))
        rename<EditObjectCommand>(name_, doc_->object(index_));
}

void ObjectProperties::assignMaterial() {
    const Scene& scene = doc_->scene();
    const int m = material_->currentIndex();
    if (index_ < 0 || index_ >= int(scene.objects.size()) || m < 0 || m >= int(scene.materials.size())) return;
    Object o = scene.objects[size_t(index_)];
    if (o.material == scene.materials[size_t(m)].name) return;
    const QString text = tr("Assign %1 to %2").arg(QString::fromStdString(scene.materials[size_t(m)].name),
                                                   QString::fromStdString(o.name));
    o.material = scene.materials[size_t(m)].name;  // the world mesh does not depend on it
    doc_->undoStack()->push(new EditObjectCommand(doc_, index_, std::move(o), 0, text));
    emit materialAssigned(m);
}

void ObjectProperties::markPortal(bool portal) {
    const Scene& scene = doc_->scene();
    if (index_ < 0 || index_ >= int(scene.objects.size())) return;
    Object o = scene.objects[size_t(index_)];
    if (o.portal == portal) return;
    o.portal = portal;
    const QString name = QString::fromStdString(o.name);
    const QString text = portal ? tr("Make %1 an opening").arg(name) : tr("Make %1 a surface").arg(name);
    doc_->undoStack()->push(new EditObjectCommand(doc_, index_, std::move(o), 0, text));
}

}  // namespace lucerna
