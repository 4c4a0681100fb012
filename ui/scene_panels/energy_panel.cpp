#include "ui/scene_panels/energy_panel.h"

#include "ui/properties/number_fields.h"
#include "core/number_format.h"
#include "core/scene/scene_energy.h"
#include "ui/commands/energy_commands.h"
#include "ui/disconnect_children.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace lucerna {

namespace {

// A factor of the page: the setting it edits, its field's name, label and unit, and its range
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

const std::array<FactorSpec, EnergyPanel::kFactors> kSpecs = {{
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

EnergyPanel::EnergyPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* layout = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("Lighting energy by EN 15193-1: LENI = (W_L + W_P) / A. An empty field takes the "
                                "default it shows."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);

    auto* form = new QFormLayout;
    type_ = new QComboBox(this);
    type_->setObjectName("energyBuildingType");
    type_->addItem(tr("Not set (LENI not computed)"));
    for (const BuildingTypeHours& t : buildingTypes())
        type_->addItem(tr("%1 (tD %2 h, tN %3 h)").arg(QString::fromUtf8(t.name)).arg(t.daytimeHours).arg(t.nightHours));
    type_->setToolTip(tr("The building type gives the default operating hours (EN 15193:2007 Table F.1)"));
    connect(type_, &QComboBox::activated, this, &EnergyPanel::chooseBuildingType);
    form->addRow(tr("Building type"), type_);
    for (int i = 0; i < kFactors; ++i) {
        const FactorSpec& spec = kSpecs[size_t(i)];
        auto* field = new QLineEdit(this);
        field->setObjectName(spec.objectName);
        field->setClearButtonEnabled(true);
        connect(field, &QLineEdit::editingFinished, this, [this, i] { applyFactor(Factor(i)); });
        fields_[size_t(i)] = field;
        const QString unit = *spec.unit ? QStringLiteral(" [%1]").arg(QString::fromUtf8(spec.unit)) : QString();
        form->addRow(tr(spec.label) + unit, field);
    }
    layout->addLayout(form);

    auto* results = new QGroupBox(tr("Annual energy (EN 15193-1)"), this);
    auto* resultRows = new QVBoxLayout(results);
    const auto resultLabel = [&](const char* name) {
        auto* label = new QLabel(results);
        label->setObjectName(name);
        label->setWordWrap(true);
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
    message_ = new QLabel(this);
    message_->setObjectName("energyMessage");
    message_->setWordWrap(true);
    message_->setStyleSheet(QStringLiteral("color: #b00020"));
    layout->addWidget(message_);
    layout->addStretch(1);

    // Any edit may change the result: a light's power or switch, the geometry (the area).
    connect(doc_, &Document::changed, this, [this] { refresh(); });
    refresh();
}

EnergyPanel::~EnergyPanel() { disconnectChildren(this); }

void EnergyPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    refresh();
}

void EnergyPanel::refresh(bool overwriteTyped) {
    // sceneEnergy reads every vertex for the plan's extent: not while the page is hidden.
    if (!isVisible()) return;
    const Scene& scene = doc_->scene();
    const std::optional<EnergySettings>& settings = scene.energy;
    const SceneEnergy energy = sceneEnergy(scene);
    {
        const QSignalBlocker quiet(type_);
        type_->setCurrentIndex(settings ? 1 + int(settings->buildingType) : 0);
    }
    const BuildingTypeHours& type = buildingTypeHours(settings ? settings->buildingType : BuildingType::Office);
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
    for (int i = 0; i < kFactors; ++i) {
        QLineEdit* field = fields_[size_t(i)];
        field->setEnabled(settings.has_value());
        field->setPlaceholderText(defaults[i]);
        if (field->hasFocus() && !overwriteTyped) continue;  // what is being typed stays
        const std::optional<double> value = settings ? (*settings).*kSpecs[size_t(i)].member : std::nullopt;
        const QSignalBlocker quiet(field);
        field->setText(value ? QString::fromStdString(shortestNumber(*value)) : QString());
    }

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

void EnergyPanel::chooseBuildingType(int index) {
    if (index <= 0) {
        change(std::nullopt, tr("Clear the energy settings"));
        return;
    }
    const BuildingTypeHours& type = buildingTypes()[size_t(index - 1)];
    EnergySettings after = doc_->energy().value_or(EnergySettings());
    after.buildingType = type.type;
    change(after, tr("Building type %1").arg(QString::fromUtf8(type.name)));
}

void EnergyPanel::applyFactor(Factor f) {
    const std::optional<EnergySettings>& before = doc_->energy();
    if (!before) return;
    const FactorSpec& spec = kSpecs[size_t(f)];
    const QString label = tr(spec.label);
    const QString text = field(f)->text().trimmed();
    std::optional<double> value;
    if (!text.isEmpty()) {
        value = typedNumber(text);
        if (!value) {
            refuse(tr("%1: \"%2\" is not a number").arg(label, text));
            return;
        }
        const double x = *value;
        if (!((spec.loOpen ? x > spec.lo : x >= spec.lo) && x <= spec.hi)) {
            refuse(tr("%1 must be in %2%3, %4]%5")
                       .arg(label, spec.loOpen ? QStringLiteral("(") : QStringLiteral("["))
                       .arg(spec.lo)
                       .arg(spec.hi)
                       .arg(*spec.unit ? QStringLiteral(" ") + QString::fromUtf8(spec.unit) : QString()));
            return;
        }
    }
    EnergySettings after = *before;
    after.*spec.member = value;
    change(after, value ? tr("%1 %2").arg(label, QString::fromStdString(shortestNumber(*value)))
                        : tr("%1 to its default").arg(label));
}

void EnergyPanel::change(std::optional<EnergySettings> after, const QString& what) {
    if (after) {
        const std::string problem = energySettingsProblem(*after);
        if (!problem.empty()) {
            refuse(QString::fromStdString(problem));
            return;
        }
    }
    message_->clear();
    if (after == doc_->energy()) {
        refresh(true);  // e.g. "2250.0" typed over 2250: the field shows the value again
        return;
    }
    doc_->undoStack()->push(new EditEnergyCommand(doc_, std::move(after), 0, what));
}

void EnergyPanel::refuse(const QString& why) {
    message_->setText(tr("Not changed: %1").arg(why));
    refresh(true);  // the scene's values again, the field typed into included
}

}  // namespace lucerna
