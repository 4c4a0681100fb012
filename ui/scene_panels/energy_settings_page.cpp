#include "ui/scene_panels/energy_settings_page.h"

#include "core/number_format.h"
#include "core/scene/scene_energy.h"
#include "ui/disconnect_children.h"
#include "ui/properties/number_fields.h"
#include "ui/properties/property_rows.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace lucerna {

namespace {

// A factor of the tab: the setting it edits, its field's name, label and unit, and its range
// (the scene file's, core/scene/project_keys.cpp).
struct FactorSpec {
    std::optional<double> EnergySettings::*member;
    const char* objectName;
    const char* label;
    const char* unit;
    double lo;
    bool loOpen;
    double hi;
};

const std::array<FactorSpec, EnergySettingsPage::kFactors> kSpecs = {{
    {&EnergySettings::daytimeHours, "energyDaytimeHours", "Daytime operating hours tD", "h/a", 0, false, kHoursPerYear},
    {&EnergySettings::nightHours, "energyNightHours", "Night-time operating hours tN", "h/a", 0, false, kHoursPerYear},
    {&EnergySettings::constantIlluminanceFactor, "energyConstantIlluminanceFactor", "Constant illuminance factor Fc", "",
     0, false, 1},
    {&EnergySettings::occupancyFactor, "energyOccupancyFactor", "Occupancy dependency factor Fo", "", 0, false, 1},
    {&EnergySettings::daylightFactor, "energyDaylightFactor", "Daylight dependency factor FD", "", 0, false, 1},
    {&EnergySettings::controlParasiticWatts, "energyControlParasiticWatts", "Parasitic power of controls Ppc",
     "W each", 0, false, 1e6},
    {&EnergySettings::emergencyChargingWatts, "energyEmergencyChargingWatts", "Emergency charging power Pem", "W each",
     0, false, 1e6},
    {&EnergySettings::emergencyChargingHours, "energyEmergencyChargingHours", "Emergency charging hours tem", "h/a", 0,
     false, kHoursPerYear},
    {&EnergySettings::areaM2, "energyArea", "Floor area A", "m\u00b2", 0, true, 1e9},
}};

QString number(double x, int decimals) { return QString::number(x, 'f', decimals); }

const QString kPerM2Year = QStringLiteral("kWh/(m\u00b2\u00b7a)");

}  // namespace

EnergySettingsPage::EnergySettingsPage(SceneSnapshot scene, QWidget* parent)
    : ProjectSettingsPage(parent), scene_(std::move(scene)) {
    setObjectName("energyPage");
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(makeWrappingLabel(
        this, "energyHelp",
        tr("Lighting energy by EN 15193-1: LENI = (W_L + W_P) / A, in the report's energy section. An empty "
           "field takes the default it shows in grey.")));

    auto* form = new QFormLayout;
    type_ = new QComboBox(this);
    type_->setObjectName("energyBuildingType");
    type_->addItem(tr("Not set (LENI not computed)"));
    for (const BuildingTypeHours& t : buildingTypes())
        type_->addItem(tr("%1 (tD %2 h, tN %3 h)").arg(QString::fromUtf8(t.name)).arg(t.daytimeHours).arg(t.nightHours));
    type_->setToolTip(tr("The building type gives the default operating hours (EN 15193:2007 Table F.1)"));
    connect(type_, &QComboBox::activated, this, &EnergySettingsPage::refresh);
    form->addRow(tr("Building type"), type_);
    for (int i = 0; i < kFactors; ++i) {
        const FactorSpec& spec = kSpecs[size_t(i)];
        auto* field = new QLineEdit(this);
        field->setObjectName(spec.objectName);
        field->setClearButtonEnabled(true);
        // A value counts when the field is left or Enter pressed, as in the light's properties.
        connect(field, &QLineEdit::editingFinished, this, &EnergySettingsPage::refresh);
        fields_[size_t(i)] = field;
        const QString unit = *spec.unit ? QStringLiteral(" [%1]").arg(QString::fromUtf8(spec.unit)) : QString();
        form->addRow(tr(spec.label) + unit, field);
    }
    layout->addLayout(form);

    auto* results = new QGroupBox(tr("Annual energy (EN 15193-1)"), this);
    auto* resultRows = new QVBoxLayout(results);
    const auto resultLabel = [&](const char* name) {
        auto* label = makeWrappingLabel(results, name);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        resultRows->addWidget(label);
        return label;
    };
    installed_ = resultLabel("energyInstalled");
    lighting_ = resultLabel("energyLightingEnergy");
    parasitic_ = resultLabel("energyParasiticEnergy");
    leni_ = resultLabel("energyLeni");
    QFont bold = leni_->font();
    bold.setBold(true);
    leni_->setFont(bold);
    layout->addWidget(results);
    message_ = makeWrappingLabel(this, "energyMessage");
    message_->setStyleSheet(QStringLiteral("color: #b00020"));
    layout->addWidget(message_);
    layout->addStretch(1);
}

EnergySettingsPage::~EnergySettingsPage() { disconnectChildren(this); }

void EnergySettingsPage::load(const ProjectSettings& settings) {
    loaded_ = settings.energy;
    type_->setCurrentIndex(loaded_ ? 1 + int(loaded_->buildingType) : 0);
    for (int i = 0; i < kFactors; ++i) {
        const std::optional<double> value = loaded_ ? (*loaded_).*kSpecs[size_t(i)].member : std::nullopt;
        loadedText_[size_t(i)] = value ? QString::fromStdString(shortestNumber(*value)) : QString();
        fields_[size_t(i)]->setText(loadedText_[size_t(i)]);
    }
    refresh();
}

EnergySettingsPage::Shown EnergySettingsPage::shown() const {
    Shown s;
    const int index = type_->currentIndex();
    if (index <= 0) return s;  // "Not set": the factors wait, whatever they hold
    EnergySettings e = loaded_.value_or(EnergySettings());
    e.buildingType = buildingTypes()[size_t(index - 1)].type;
    for (int i = 0; i < kFactors; ++i) {
        const FactorSpec& spec = kSpecs[size_t(i)];
        const QString text = fields_[size_t(i)]->text().trimmed();
        if (text == loadedText_[size_t(i)]) continue;  // untouched: the loaded value, exactly
        std::optional<double> value;
        if (!text.isEmpty()) {
            value = typedNumber(text);
            const QString label = tr(spec.label);
            if (!value) {
                s.problem = tr("%1: \"%2\" is not a number").arg(label, text);
            } else if (const double x = *value; !((spec.loOpen ? x > spec.lo : x >= spec.lo) && x <= spec.hi)) {
                s.problem = tr("%1 must be in %2%3, %4]%5")
                                .arg(label, spec.loOpen ? QStringLiteral("(") : QStringLiteral("["))
                                .arg(spec.lo)
                                .arg(spec.hi)
                                .arg(*spec.unit ? QStringLiteral(" ") + QString::fromUtf8(spec.unit) : QString());
            }
            if (!s.problem.isEmpty()) {
                s.badField = i;
                return s;
            }
        }
        e.*spec.member = value;
    }
    if (const std::string problem = energySettingsProblem(e); !problem.empty()) {
        s.problem = QString::fromStdString(problem);
        return s;
    }
    s.settings = e;
    return s;
}

void EnergySettingsPage::store(ProjectSettings& settings) const {
    Shown s = shown();
    if (s.problem.isEmpty()) settings.energy = std::move(s.settings);
}

void EnergySettingsPage::showEvent(QShowEvent* event) {
    ProjectSettingsPage::showEvent(event);
    refresh();
}

QString EnergySettingsPage::check() {
    refresh();
    const Shown s = shown();
    if (s.badField >= 0) fields_[size_t(s.badField)]->setFocus();
    return s.problem;
}

void EnergySettingsPage::refresh() {
    const Shown s = shown();
    message_->setText(s.problem);
    const bool set = type_->currentIndex() > 0;
    for (QLineEdit* field : fields_) field->setEnabled(set);
    // The results stay those of the last settings without a problem until it is corrected, and
    // wait for the tab to be shown: sceneEnergy reads every vertex for the plan's extent.
    if (!s.problem.isEmpty() || !isVisible()) return;

    Scene scene = *scene_;  // meshes are shared: the copy costs the lists only
    scene.energy = s.settings;
    const SceneEnergy energy = sceneEnergy(scene);
    const BuildingTypeHours& type = buildingTypeHours(set ? s.settings->buildingType : BuildingType::Office);
    const QString typeName = QString::fromUtf8(type.name).toLower();
    const QString defaults[kFactors] = {
        tr("%1 (default for %2)").arg(type.daytimeHours).arg(typeName),
        tr("%1 (default for %2)").arg(type.nightHours).arg(typeName),
        tr("1 (default: no constant-illuminance control)"),
        tr("1 (default: no occupancy control)"),
        tr("1 (default: no daylight control)"),
        tr("none: %1 %2 \u00d7 A").arg(kDefaultControlParasiticKWhPerM2).arg(kPerM2Year),
        tr("none: %1 %2 \u00d7 A").arg(kDefaultEmergencyParasiticKWhPerM2).arg(kPerM2Year),
        tr("8760 (default: charging all year)"),
        tr("%1 (the extent in plan)").arg(number(energy.planAreaM2, 1)),
    };
    for (int i = 0; i < kFactors; ++i) fields_[size_t(i)]->setPlaceholderText(defaults[i]);

    const int counted = energy.lights - int(energy.withoutPower.size());
    double watts = 0;
    for (const EnergyLightType& t : energy.types) watts += t.wattsEach * double(t.names.size());
    QString installed = energy.lights == 1 ? tr("1 electric light switched on")
                                           : tr("%1 electric lights switched on").arg(energy.lights);
    if (counted > 0) installed += tr(", %1 W installed").arg(number(watts, 1));
    if (const size_t n = energy.withoutPower.size(); n > 0)
        installed += (n == 1 ? tr("; 1 states no power") : tr("; %1 state no power").arg(n)) +
                     tr(" (a light's Circuit power, in its properties)");
    installed_->setText(installed);
    if (energy.energy) {
        const LightingEnergy& e = *energy.energy;
        lighting_->setText(tr("W_L = %1 kWh/a").arg(number(e.lightingKWh, 1)));
        parasitic_->setText(tr("W_P = %1 kWh/a (controls %2, emergency %3)")
                                .arg(number(e.parasiticKWh, 1), number(e.controlParasiticKWh, 1),
                                     number(e.emergencyParasiticKWh, 1)));
        leni_->setText(tr("LENI = %1 %2 (A = %3 m\u00b2)").arg(number(e.leni, 2), kPerM2Year, number(e.areaM2.value, 1)));
    } else {
        lighting_->setText(tr("W_L: -"));
        parasitic_->setText(tr("W_P: -"));
        leni_->setText(tr("LENI not computed: %1").arg(QString::fromStdString(energy.notComputed)));
    }
}

}  // namespace lucerna
