#include "ui/properties/material_properties.h"

#include "ui/properties/colour_edit.h"
#include "ui/commands/material_commands.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QVBoxLayout>

namespace lucerna {

namespace {
constexpr int kSliderSteps = 1000;  // roughness slider: (0, 1] in steps of 0.001
constexpr MaterialType kTypes[] = {MaterialType::Diffuse, MaterialType::Glossy, MaterialType::Mirror,
                                   MaterialType::Dielectric, MaterialType::Emitter, MaterialType::Glazing};
}  // namespace

MaterialProperties::MaterialProperties(Document* doc, QWidget* parent)
    : ItemProperties(doc, tr("Select an object, a light or a material in the outliner."), parent) {
    name_ = new QLabel(fields_);
    name_->setObjectName("materialName");
    QFont bold = name_->font();
    bold.setBold(true);
    name_->setFont(bold);
    type_ = new QComboBox(fields_);
    type_->setObjectName("materialType");
    for (MaterialType t : kTypes) type_->addItem(materialTypeName(t), int(t));
    addPropertyRow(rows_, tr("Material"), {name_});
    addPropertyRow(rows_, tr("Type"), {type_});

    albedo_ = new ColourEdit(1.0, fields_);
    albedo_->setObjectName("materialAlbedo");
    albedoRow_ = addPropertyRow(rows_, tr("Albedo"), {albedo_});
    specular_ = new ColourEdit(1.0, fields_);
    specular_->setObjectName("materialSpecular");
    specularRow_ = addPropertyRow(rows_, tr("Specular"), {specular_});

    roughnessSlider_ = new QSlider(Qt::Horizontal, fields_);
    roughnessSlider_->setObjectName("materialRoughnessSlider");
    roughnessSlider_->setRange(1, kSliderSteps);
    roughness_ = makePropertySpin(fields_, 0.001, 1.0, 3);  // SPEC.md: alpha in (0, 1]
    roughness_->setObjectName("materialRoughness");
    roughness_->setSingleStep(0.01);
    roughness_->setMaximumWidth(80);
    roughnessRow_ = addPropertyRow(rows_, tr("Roughness (α)"), {roughnessSlider_, roughness_});

    reflectance_ = new ColourEdit(1.0, fields_);
    reflectance_->setObjectName("materialReflectance");
    reflectanceRow_ = addPropertyRow(rows_, tr("Reflectance"), {reflectance_});
    ior_ = makePropertySpin(fields_, 0.01, 10.0, 4);  // SPEC.md: ior > 0
    ior_->setObjectName("materialIor");
    ior_->setSingleStep(0.01);
    iorRow_ = addPropertyRow(rows_, tr("Index of refraction"), {ior_});
    radiance_ = new ColourEdit(1e9, fields_);
    radiance_->setObjectName("materialRadiance");
    radianceRow_ = addPropertyRow(rows_, tr("Radiance\n(W sr⁻¹ m⁻²)"), {radiance_});
    luminance_ = new QLabel(fields_);
    luminance_->setObjectName("materialLuminance");
    luminanceRow_ = addPropertyRow(rows_, tr("Luminance"), {luminance_});
    transmittance_ = new ColourEdit(1.0, fields_);
    transmittance_->setObjectName("materialTransmittance");
    transmittanceRow_ = addPropertyRow(rows_, tr("Transmittance"), {transmittance_});
    rows_->addStretch(1);  // rows packed at the top while hidden ones still count in the hint

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(empty_);
    layout->addWidget(fields_);

    connect(type_, &QComboBox::activated, this, [this] {
        const Scene& scene = doc_->scene();
        if (index_ < 0 || index_ >= int(scene.materials.size())) return;
        const Material& m = scene.materials[size_t(index_)];
        push(withMaterialType(m, MaterialType(type_->currentData().toInt())), type_, tr("Change type of %1"));
        merge_.finish();
    });
    for (ColourEdit* c : {albedo_, specular_, reflectance_, radiance_, transmittance_}) {
        connect(c, &ColourEdit::edited, this, &MaterialProperties::applyFields);
        connect(c, &ColourEdit::editingFinished, this, [this] { merge_.finish(); });
    }
    connect(roughnessSlider_, &QSlider::valueChanged, this, [this](int v) {
        const QSignalBlocker block(roughness_);
        roughness_->setValue(double(v) / kSliderSteps);
        applyFields(roughnessSlider_);
        // A click on the track or a key is a step of its own; a drag merges until it is let go.
        if (!roughnessSlider_->isSliderDown()) merge_.finish();
    });
    connect(roughnessSlider_, &QSlider::sliderPressed, this, [this] { merge_.finish(); });
    connect(roughnessSlider_, &QSlider::sliderReleased, this, [this] { merge_.finish(); });
    connect(roughness_, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        const QSignalBlocker block(roughnessSlider_);
        roughnessSlider_->setValue(int(std::lround(v * kSliderSteps)));
        applyFields(roughness_);
    });
    for (QDoubleSpinBox* s : {roughness_, ior_})
        connect(s, &QDoubleSpinBox::editingFinished, this, [this] { merge_.finish(); });
    connect(ior_, &QDoubleSpinBox::valueChanged, this, [this] { applyFields(ior_); });

    connect(doc_, &Document::changed, this, &MaterialProperties::refresh);
    refresh();
}

void MaterialProperties::refresh() {
    const Scene& scene = doc_->scene();
    if (!showsItem(scene.materials.size())) return;
    const Material& m = scene.materials[size_t(index_)];
    name_->setText(QString::fromStdString(m.name));
    {
        const QSignalBlocker b1(type_), b2(roughnessSlider_), b3(roughness_), b4(ior_);
        type_->setCurrentIndex(type_->findData(int(m.type)));
        roughness_->setValue(m.roughness);
        roughnessSlider_->setValue(int(std::lround(m.roughness * kSliderSteps)));
        ior_->setValue(m.ior);
    }
    albedo_->setValue(m.albedo);
    specular_->setValue(m.specular);
    reflectance_->setValue(m.reflectance);
    radiance_->setValue(m.radiance);
    transmittance_->setValue(m.transmittance);
    luminance_->setText(tr("%1 cd/m²").arg(kLumensPerWatt * luminance(m.radiance), 0, 'g', 5));

    const MaterialType t = m.type;
    albedoRow_->setVisible(t == MaterialType::Diffuse || t == MaterialType::Glossy);
    specularRow_->setVisible(t == MaterialType::Glossy);
    roughnessRow_->setVisible(t == MaterialType::Glossy);
    reflectanceRow_->setVisible(t == MaterialType::Mirror);
    iorRow_->setVisible(t == MaterialType::Dielectric);
    radianceRow_->setVisible(t == MaterialType::Emitter);
    luminanceRow_->setVisible(t == MaterialType::Emitter);
    transmittanceRow_->setVisible(t == MaterialType::Glazing);
}

void MaterialProperties::applyFields(const void* source) {
    const Scene& scene = doc_->scene();
    if (index_ < 0 || index_ >= int(scene.materials.size())) return;
    Material m = scene.materials[size_t(index_)];
    QString what;
    // Only the field that changed: the others show values rounded to their decimals, which must
    // not be written back.
    const auto take = [source](const ColourEdit* edit, Rgbd& value) {
        if (source == edit->swatch()) value = edit->value();
        for (int c = 0; c < 3; ++c)
            if (source == edit->channel(c)) value[c] = edit->channel(c)->value();
    };
    take(albedo_, m.albedo);
    take(specular_, m.specular);
    take(reflectance_, m.reflectance);
    take(radiance_, m.radiance);
    take(transmittance_, m.transmittance);
    if (source == roughnessSlider_ || source == roughness_) m.roughness = roughness_->value();
    if (source == ior_) m.ior = ior_->value();
    if (source == roughnessSlider_ || source == roughness_) what = tr("Change roughness of %1");
    else if (source == ior_) what = tr("Change index of refraction of %1");
    else if (m.type == MaterialType::Emitter) what = tr("Change radiance of %1");
    else if (m.type == MaterialType::Glazing) what = tr("Change transmittance of %1");
    else what = tr("Change colour of %1");
    push(std::move(m), source, what);
}

void MaterialProperties::push(Material m, const void* source, const QString& what) {
    const Material& old = doc_->scene().materials[size_t(index_)];
    if (m == old) return;
    // SPEC.md bounds, which the fields' ranges keep; checked again so that no path around them
    // (a picked colour, a future field) writes a scene the loader would reject.
    const auto unit = [](const Rgbd& c) { return c.x >= 0 && c.x <= 1 && c.y >= 0 && c.y <= 1 && c.z >= 0 && c.z <= 1; };
    const bool ok = unit(m.albedo) && unit(m.specular) && unit(m.reflectance) && unit(m.transmittance) && m.roughness > 0 &&
                    m.roughness <= 1 && m.ior > 0 && m.radiance.x >= 0 && m.radiance.y >= 0 && m.radiance.z >= 0;
    if (!ok) {
        refresh();
        return;
    }
    const QString text = what.arg(QString::fromStdString(m.name));
    doc_->undoStack()->push(new EditMaterialCommand(doc_, index_, std::move(m), merge_.keyFor(source), text));
}

}  // namespace lucerna
