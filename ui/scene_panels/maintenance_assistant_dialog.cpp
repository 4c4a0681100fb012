#include "ui/scene_panels/maintenance_assistant_dialog.h"

#include "ui/properties/number_fields.h"
#include "core/scene/scene_geometry.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <stdexcept>

namespace lucerna {

namespace {

// A list of an enumeration's values by their names, the item's data its value.
template <class Enum, size_t N>
QComboBox* enumList(QWidget* parent, const char* name, const Enum (&values)[N], const char* (*label)(Enum), Enum current) {
    auto* box = new QComboBox(parent);
    box->setObjectName(name);
    for (Enum v : values) box->addItem(QString::fromUtf8(label(v)), int(v));
    box->setCurrentIndex(box->findData(int(current)));
    return box;
}

constexpr Cleanliness kEnvironments[] = {Cleanliness::VeryClean, Cleanliness::Clean, Cleanliness::Normal,
                                         Cleanliness::Dirty};
constexpr LuminaireClass kLuminaires[] = {LuminaireClass::A, LuminaireClass::B, LuminaireClass::C, LuminaireClass::D,
                                          LuminaireClass::E, LuminaireClass::F, LuminaireClass::G};
constexpr LightDistribution kDistributions[] = {LightDistribution::Direct, LightDistribution::DirectIndirect,
                                                LightDistribution::Indirect};

template <class Enum> Enum chosen(const QComboBox* box) { return Enum(box->currentData().toInt()); }

}  // namespace

MaintenanceAssistantDialog::MaintenanceAssistantDialog(const MaintenanceChoices& initial, QWidget* parent,
                                                       const Cie97Tables& tables)
    : QDialog(parent), tables_(tables) {
    setObjectName("maintenanceAssistant");
    setWindowTitle(tr("Maintenance factor assistant (CIE 97:2005)"));

    // The lamp: LLMF and LSF.
    auto* lampBox = new QGroupBox(tr("Lamp (LLMF, LSF)"), this);
    lamp_ = new QComboBox(lampBox);
    lamp_->setObjectName("assistantLamp");
    lamp_->addItem(tr("LED, by its rating Lx at a rated life"), QString::fromUtf8(kLedLamp));
    for (const Cie97Tables::LampFamily& f : tables.lamps)
        lamp_->addItem(QString::fromStdString(f.name), QString::fromStdString(f.name));
    lamp_->addItem(tr("Other (the lamp maker's data)"), QString::fromUtf8(kMakersDataLamp));
    lamp_->setCurrentIndex(std::max(0, lamp_->findData(QString::fromStdString(initial.lamp))));
    ledRating_ = makeNumberField(lampBox, "assistantLedRating", 100 * initial.ledLumenFraction, 1, 99, {}, 0);
    ledRating_->setPrefix(QStringLiteral("L"));
    ledRating_->setToolTip(tr("The flux left at the rated life: L80 keeps 80%"));
    ledLife_ = makeNumberField(lampBox, "assistantLedLife", initial.ledRatedLifeHours, 1, 1e6, tr(" h"), 0, 1000);
    hours_ = makeNumberField(lampBox, "assistantHours", initial.operatingHours, 1, 1e6, tr(" h"), 0, 1000);
    hours_->setToolTip(tr("Operating hours between group replacements, or to the end of the maintenance period"));
    spotReplacement_ = new QCheckBox(tr("Failed lamps are replaced at once (spot replacement)"), lampBox);
    spotReplacement_->setObjectName("assistantSpotReplacement");
    spotReplacement_->setChecked(initial.spotReplacement);
    auto* lampForm = new QFormLayout(lampBox);
    lampForm->addRow(tr("Lamp"), lamp_);
    lampForm->addRow(tr("LED rating"), ledRating_);
    lampForm->addRow(tr("LED rated life"), ledLife_);
    lampForm->addRow(tr("Operating hours"), hours_);
    lampForm->addRow(spotReplacement_);
    ledRow_ = ledRating_;
    ledLifeRow_ = ledLife_;

    // The luminaire: LMF.
    auto* luminaireBox = new QGroupBox(tr("Luminaire (LMF, CIE 97:2005 Table 3)"), this);
    luminaire_ = enumList(luminaireBox, "assistantLuminaire", kLuminaires, luminaireClassName, initial.luminaire);
    luminaireEnvironment_ = enumList(luminaireBox, "assistantLuminaireEnvironment", kEnvironments, cleanlinessName,
                                     initial.luminaireEnvironment);
    luminaireCleaning_ = makeNumberField(luminaireBox, "assistantLuminaireCleaning", initial.luminaireCleaningYears, 0.5, 3,
                               tr(" years"), 2, 0.5);
    auto* luminaireForm = new QFormLayout(luminaireBox);
    luminaireForm->addRow(tr("Luminaire type"), luminaire_);
    luminaireForm->addRow(tr("Environment"), luminaireEnvironment_);
    luminaireForm->addRow(tr("Cleaned every"), luminaireCleaning_);

    // The room: K and RSMF.
    auto* roomBox = new QGroupBox(tr("Room (RSMF, CIE 97:2005 Table 4)"), this);
    length_ = makeNumberField(roomBox, "assistantRoomLength", initial.roomLengthM, 0.1, 1e4, tr(" m"), 2);
    width_ = makeNumberField(roomBox, "assistantRoomWidth", initial.roomWidthM, 0.1, 1e4, tr(" m"), 2);
    height_ = makeNumberField(roomBox, "assistantMountingHeight", initial.mountingHeightM, 0.1, 1e3, tr(" m"), 2, 0.1);
    height_->setToolTip(tr("The luminaires' height above the work plane"));
    roomIndex_ = new QLabel(roomBox);
    roomIndex_->setObjectName("assistantRoomIndex");
    distribution_ = enumList(roomBox, "assistantDistribution", kDistributions, distributionName, initial.distribution);
    roomEnvironment_ =
        enumList(roomBox, "assistantRoomEnvironment", kEnvironments, cleanlinessName, initial.roomEnvironment);
    roomCleaning_ = makeNumberField(roomBox, "assistantRoomCleaning", initial.roomCleaningYears, 0.5, 3, tr(" years"), 2, 0.5);
    auto* roomForm = new QFormLayout(roomBox);
    roomForm->addRow(tr("Length"), length_);
    roomForm->addRow(tr("Width"), width_);
    roomForm->addRow(tr("Mounting height"), height_);
    roomForm->addRow(tr("Room index"), roomIndex_);
    roomForm->addRow(tr("Distribution"), distribution_);
    roomForm->addRow(tr("Environment"), roomEnvironment_);
    roomForm->addRow(tr("Surfaces cleaned every"), roomCleaning_);

    // Choices a table that is not there cannot use are shown, but inert.
    for (QWidget* w : {static_cast<QWidget*>(luminaire_), static_cast<QWidget*>(luminaireEnvironment_),
                       static_cast<QWidget*>(luminaireCleaning_)})
        w->setEnabled(tables.hasLmf());
    for (QWidget* w : {static_cast<QWidget*>(distribution_), static_cast<QWidget*>(roomEnvironment_),
                       static_cast<QWidget*>(roomCleaning_)})
        w->setEnabled(tables.hasRsmf());

    result_ = new QLabel(this);
    result_->setObjectName("assistantResult");
    result_->setWordWrap(true);
    result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    result_->setMinimumWidth(560);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    ok_ = buttons->button(QDialogButtonBox::Ok);
    ok_->setText(tr("Fill in the factors found"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* columns = new QHBoxLayout;
    auto* left = new QVBoxLayout;
    left->addWidget(lampBox);
    left->addWidget(luminaireBox);
    left->addStretch(1);
    columns->addLayout(left);
    columns->addWidget(roomBox, 0, Qt::AlignTop);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns);
    layout->addWidget(result_);
    layout->addWidget(buttons);

    for (QDoubleSpinBox* s : {ledRating_, ledLife_, hours_, luminaireCleaning_, length_, width_, height_, roomCleaning_})
        connect(s, &QDoubleSpinBox::valueChanged, this, &MaintenanceAssistantDialog::update);
    for (QComboBox* c : {lamp_, luminaire_, luminaireEnvironment_, distribution_, roomEnvironment_})
        connect(c, &QComboBox::currentIndexChanged, this, &MaintenanceAssistantDialog::update);
    connect(spotReplacement_, &QCheckBox::toggled, this, &MaintenanceAssistantDialog::update);
    // The LED's rating rows only for an LED.
    connect(lamp_, &QComboBox::currentIndexChanged, this, [this, lampForm] {
        const bool led = lamp_->currentData().toString() == QString::fromUtf8(kLedLamp);
        lampForm->setRowVisible(ledRow_, led);
        lampForm->setRowVisible(ledLifeRow_, led);
    });
    emit lamp_->currentIndexChanged(lamp_->currentIndex());
    update();
}

MaintenanceChoices MaintenanceAssistantDialog::choices() const {
    MaintenanceChoices c;
    c.lamp = lamp_->currentData().toString().toStdString();
    c.ledLumenFraction = ledRating_->value() / 100;
    c.ledRatedLifeHours = ledLife_->value();
    c.operatingHours = hours_->value();
    c.spotReplacement = spotReplacement_->isChecked();
    c.luminaire = chosen<LuminaireClass>(luminaire_);
    c.luminaireEnvironment = chosen<Cleanliness>(luminaireEnvironment_);
    c.luminaireCleaningYears = luminaireCleaning_->value();
    c.roomLengthM = length_->value();
    c.roomWidthM = width_->value();
    c.mountingHeightM = height_->value();
    c.distribution = chosen<LightDistribution>(distribution_);
    c.roomEnvironment = chosen<Cleanliness>(roomEnvironment_);
    c.roomCleaningYears = roomCleaning_->value();
    return c;
}

void MaintenanceAssistantDialog::update() {
    try {
        assessment_ = assessMaintenance(choices(), tables_);
    } catch (const std::invalid_argument& e) {
        assessment_.reset();
        roomIndex_->clear();
        result_->setText(QString::fromStdString(e.what()));
        ok_->setEnabled(false);
        return;
    }
    const MaintenanceAssessment& a = *assessment_;
    roomIndex_->setText(tables_.hasRsmf() ? tr("K = %1 (a %2 room)").arg(a.roomIndex, 0, 'f', 2).arg(roomSizeName(a.roomSize))
                                          : tr("K = %1").arg(a.roomIndex, 0, 'f', 2));
    QStringList lines;
    for (const FoundFactor* f : {&a.llmf, &a.lsf, &a.lmf, &a.rsmf}) lines << QString::fromStdString(f->explanation);
    if (const std::optional<MaintenanceFactor> mf = a.factors())
        lines << tr("Found so far: MF = %1 (factors not found count 1 until typed).").arg(mf->factor(), 0, 'f', 3);
    result_->setText(lines.join('\n'));
    ok_->setEnabled(a.factors().has_value());
}

MaintenanceChoices choicesForScene(const Scene& scene) {
    MaintenanceChoices c;
    if (scene.objects.empty()) return c;
    const SceneBounds b = sceneBounds(scene);
    const double m = scene.metersPerUnit;
    double top = b.lo.y;
    bool lit = false;
    for (const Light& l : scene.lights)
        if (l.type == LightType::Point || l.type == LightType::Spot || l.type == LightType::Luminaire) {
            top = lit ? std::max(top, l.position.y) : l.position.y;
            lit = true;
        }
    if (!lit) top = b.hi.y;
    c.roomLengthM = std::max(0.1, (b.hi.x - b.lo.x) * m);
    c.roomWidthM = std::max(0.1, (b.hi.z - b.lo.z) * m);
    c.mountingHeightM = std::max(0.1, (top - b.lo.y) * m - 0.8);
    return c;
}

}  // namespace lucerna
