#include "ui/light_properties.h"

#include "core/luminaire.h"
#include "core/scene_geometry.h"
#include "ui/commands/light_commands.h"
#include "ui/viewport.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace lucerna {

LightProperties::LightProperties(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    empty_ = new QLabel(tr("Select a light in the outliner or the viewport."), this);
    empty_->setWordWrap(true);
    fields_ = new QWidget(this);
    rows_ = new QVBoxLayout(fields_);
    rows_->setContentsMargins(0, 0, 0, 0);
    fields_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);  // rows packed at the top
    name_ = new QLineEdit(fields_);
    name_->setObjectName("lightName");
    type_ = new QLabel(fields_);
    addRow(tr("Name"), {name_});
    addRow(tr("Type"), {type_});
    position_ = makeTriple(positionRow_, Field::Position, tr("Position"));
    positionLabel_ = positionRow_->findChild<QLabel*>();
    positionLabel_->setObjectName("positionLabel");
    direction_ = makeTriple(directionRow_, Field::Direction, tr("Direction"));
    directionLabel_ = directionRow_->findChild<QLabel*>();
    power_ = makeTriple(powerRow_, Field::Power, tr("Intensity"));
    powerLabel_ = powerRow_->findChild<QLabel*>();
    powerLabel_->setObjectName("powerLabel");
    cone_ = makeSpin(Field::Cone);
    cone_->setRange(0.1, 179.9);
    cone_->setSuffix(QStringLiteral(" °"));
    cone_->setObjectName("lightCone");
    falloff_ = makeSpin(Field::Falloff);
    falloff_->setRange(0.1, 179.9);
    falloff_->setSuffix(QStringLiteral(" °"));
    falloff_->setObjectName("lightFalloff");
    coneRow_ = addRow(tr("Cone half-angle"), {cone_});
    falloffRow_ = addRow(tr("Falloff start"), {falloff_});
    file_ = new QLabel(fields_);
    file_->setObjectName("luminaireFile");
    file_->setWordWrap(true);
    fileRow_ = addRow(tr("Photometry"), {file_});
    rotation_ = makeSpin(Field::Rotation);
    rotation_->setRange(-360, 360);
    rotation_->setSuffix(QStringLiteral(" °"));
    rotation_->setObjectName("luminaireRotation");
    rotationRow_ = addRow(tr("Rotation"), {rotation_});
    lumens_ = makeSpin(Field::Lumens);
    lumens_->setRange(0, 1e9);
    lumens_->setDecimals(1);
    lumens_->setSuffix(QStringLiteral(" lm"));
    lumens_->setObjectName("luminaireLumens");
    lumensRow_ = addRow(tr("Flux"), {lumens_});
    rows_->addStretch(1);
    for (int i = 0; i < 3; ++i) {
        position_[size_t(i)]->setObjectName(QStringLiteral("lightPosition%1").arg(i));
        position_[size_t(i)]->setDecimals(2);
        direction_[size_t(i)]->setObjectName(QStringLiteral("lightDirection%1").arg(i));
        direction_[size_t(i)]->setRange(-1e6, 1e6);
        direction_[size_t(i)]->setDecimals(4);
        direction_[size_t(i)]->setSingleStep(0.05);
        power_[size_t(i)]->setObjectName(QStringLiteral("lightPower%1").arg(i));
        power_[size_t(i)]->setRange(0, 1e12);
        power_[size_t(i)]->setDecimals(4);
    }
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(empty_);
    layout->addWidget(fields_);
    layout->addStretch(1);

    connect(name_, &QLineEdit::editingFinished, this, &LightProperties::renameLight);
    connect(doc_, &Document::lightChanged, this, [this](int i) {
        if (i == index_) refresh();
    });
    connect(doc_, &Document::structureChanged, this, &LightProperties::refresh);
    refresh();
}

QDoubleSpinBox* LightProperties::makeSpin(Field field) {
    auto* spin = new QDoubleSpinBox(fields_);
    // Typed values count when Enter is pressed or the field is left, not at every keystroke.
    spin->setKeyboardTracking(false);
    spin->setRange(-1e9, 1e9);
    spin->setDecimals(3);
    spin->setAccelerated(true);
    // A spin box asks for the width of its longest value; three in a row would widen the dock
    // past the viewport. Let the layout share the width instead.
    spin->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    spin->setMinimumWidth(70);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, field, spin] { apply(field, spin); });
    // A new edit of this field after editing finished is a new undo step.
    connect(spin, &QDoubleSpinBox::editingFinished, this, [this] { lastField_ = nullptr; });
    return spin;
}

QWidget* LightProperties::addRow(const QString& label, std::initializer_list<QWidget*> fields) {
    // Rows of their own (not a QFormLayout) so that a hidden row leaves no gap.
    auto* row = new QWidget(fields_);
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    auto* l = new QLabel(label, row);
    l->setMinimumWidth(110);
    h->addWidget(l);
    for (QWidget* f : fields) h->addWidget(f, 1);
    rows_->addWidget(row);
    return row;
}

std::array<QDoubleSpinBox*, 3> LightProperties::makeTriple(QWidget*& row, Field field, const QString& label) {
    std::array<QDoubleSpinBox*, 3> spins{};
    for (auto& s : spins) s = makeSpin(field);
    row = addRow(label, {spins[0], spins[1], spins[2]});
    return spins;
}

void LightProperties::setLight(int index) {
    index_ = index;
    lastField_ = nullptr;
    refresh();
}

void LightProperties::refresh() {
    const Scene& scene = doc_->scene();
    const bool valid = index_ >= 0 && index_ < int(scene.lights.size());
    empty_->setVisible(!valid);
    fields_->setVisible(valid);
    if (!valid) return;
    const Light& l = scene.lights[size_t(index_)];
    const QList<QWidget*> all = fields_->findChildren<QWidget*>();
    std::vector<std::unique_ptr<QSignalBlocker>> blocks;
    for (QWidget* w : all) blocks.push_back(std::make_unique<QSignalBlocker>(w));

    if (!name_->hasFocus() || name_->text().isEmpty()) name_->setText(QString::fromStdString(l.name));
    type_->setText(lightTypeName(l.type));
    const bool positioned = l.type != LightType::Directional;
    const bool spot = l.type == LightType::Spot;
    const bool luminaire = l.type == LightType::Luminaire && l.luminaire;
    positionRow_->setVisible(positioned);
    directionRow_->setVisible(l.type != LightType::Point);
    directionLabel_->setText(luminaire ? tr("Nadir") : tr("Direction"));
    coneRow_->setVisible(spot);
    falloffRow_->setVisible(spot);
    // A luminaire's output is its file's distribution, scaled to a flux: no intensity field.
    powerRow_->setVisible(!luminaire);
    fileRow_->setVisible(luminaire);
    rotationRow_->setVisible(luminaire);
    lumensRow_->setVisible(luminaire);
    if (luminaire) {
        const LuminaireSpec& spec = *l.luminaire;
        QString file = QString::fromStdString(spec.file);
        if (spec.distribution && !spec.distribution->name.empty())
            file += QStringLiteral(" (%1)").arg(QString::fromStdString(spec.distribution->name));
        file_->setText(spec.distribution ? file : tr("%1 (not loaded)").arg(file));
        rotation_->setValue(spec.rotationDeg.value_or(0.0));
        lumens_->setValue(luminaireFlux(l));
        lumens_->setEnabled(spec.distribution != nullptr);
    }
    // Units in the labels: three values in a row leave no room for a suffix in each field.
    positionLabel_->setText(tr("Position (%1)").arg(lengthUnit(scene)));
    powerLabel_->setText(positioned ? tr("Intensity (W/sr)") : tr("Irradiance (W/m²)"));
    const Rgbd& power = positioned ? l.intensity : l.irradiance;
    for (int i = 0; i < 3; ++i) {
        position_[size_t(i)]->setValue(l.position[i]);
        direction_[size_t(i)]->setValue(l.direction[i]);
        power_[size_t(i)]->setValue(power[i]);
    }
    cone_->setValue(l.coneAngleDeg);
    falloff_->setValue(l.falloffStartDeg.value_or(l.coneAngleDeg));
}

void LightProperties::apply(Field field, QObject* sender) {
    const Scene& scene = doc_->scene();
    if (index_ < 0 || index_ >= int(scene.lights.size())) return;
    Light l = scene.lights[size_t(index_)];
    QString what;
    // Only the component that changed: the other fields show values rounded to their decimals,
    // which must not be written back.
    const auto take = [sender](const std::array<QDoubleSpinBox*, 3>& fields, V3d& value) {
        for (int i = 0; i < 3; ++i)
            if (fields[size_t(i)] == sender) value[i] = fields[size_t(i)]->value();
    };
    switch (field) {
    case Field::Position:
        take(position_, l.position);
        what = tr("Move %1");
        break;
    case Field::Direction: {
        V3d d = l.direction;
        take(direction_, d);
        // SPEC.md: directions are non-zero. Refuse the edit and show the light as it is.
        if (d.length() == 0) {
            refresh();
            return;
        }
        l.direction = d;
        what = tr("Aim %1");
        break;
    }
    case Field::Power: {
        take(power_, l.type == LightType::Directional ? l.irradiance : l.intensity);
        what = tr("Change power of %1");
        break;
    }
    case Field::Cone:
        l.coneAngleDeg = cone_->value();
        // SPEC.md: falloff_start is at most cone_angle.
        if (l.falloffStartDeg && *l.falloffStartDeg > l.coneAngleDeg) l.falloffStartDeg = l.coneAngleDeg;
        what = tr("Change cone of %1");
        break;
    case Field::Falloff:
        l.falloffStartDeg = std::min(falloff_->value(), l.coneAngleDeg);
        what = tr("Change falloff of %1");
        break;
    case Field::Rotation:
        if (!l.luminaire) return;
        l.luminaire->rotationDeg = rotation_->value();
        what = tr("Turn %1");
        break;
    case Field::Lumens:
        if (!l.luminaire) return;
        // The flux shown is after the tilt multiplier; "lumens" is the flux before it.
        if (const double tilt = l.luminaire->distribution ? l.luminaire->distribution->tiltMultiplier(
                                    luminaireTiltDeg(l.direction)) : 0.0; tilt > 0)
            l.luminaire->lumens = lumens_->value() / tilt;
        what = tr("Change flux of %1");
        break;
    }
    if (l == scene.lights[size_t(index_)]) return;
    if (sender != lastField_) {
        lastField_ = sender;
        mergeKey_ = nextMergeKey();
    }
    doc_->undoStack()->push(
        new EditLightCommand(doc_, index_, l, mergeKey_, what.arg(QString::fromStdString(l.name))));
}

void LightProperties::renameLight() {
    const Scene& scene = doc_->scene();
    if (index_ < 0 || index_ >= int(scene.lights.size())) return;
    Light l = scene.lights[size_t(index_)];
    const std::string name = name_->text().trimmed().toStdString();
    // SPEC.md: names are unique across objects and lights; an empty or taken name is refused.
    if (name == l.name || name.empty() || doc_->nameInUse(name)) {
        name_->setText(QString::fromStdString(l.name));
        return;
    }
    const QString text = tr("Rename %1 to %2").arg(QString::fromStdString(l.name), QString::fromStdString(name));
    l.name = name;
    doc_->undoStack()->push(new EditLightCommand(doc_, index_, l, 0, text));
}

}  // namespace lucerna
