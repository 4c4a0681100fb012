// The report's lighting energy section (README, "Energy (LENI; an addition)"): EN 15193-1's LENI
// with every factor it took and where each came from, the circuit power of each kind of light,
// W_L, W_P and A; or why it was not computed.

#include "report/report_pages.h"
#include "report/report_text.h"

namespace lucerna {

namespace {

const QString kM2 = QStringLiteral("m\u00b2");
const QString kPerM2Year = QStringLiteral("kWh/(m\u00b2\u00b7a)");

QString number(double x, int decimals) { return QString::number(x, 'f', decimals); }

// "2250 h/a (offices' default)" or "2000 h/a (given)".
QString hours(const UsedFactor& f, const QString& fallback) {
    return QStringLiteral("%1 h/a (%2)").arg(number(f.value, 0), f.given ? QStringLiteral("given") : fallback);
}

QString factor(const UsedFactor& f, const QString& control) {
    return f.given ? QStringLiteral("%1 (given)").arg(number(f.value, 2))
                   : QStringLiteral("%1 (default: no %2)").arg(number(f.value, 2), control);
}

std::vector<std::pair<QString, QString>> factorLines(const SceneEnergy& s) {
    const LightingEnergy& e = *s.energy;
    const BuildingTypeHours& type = buildingTypeHours(e.buildingType);
    const QString typeDefault = QStringLiteral("%1' default, EN 15193:2007 Table F.1").arg(qs(type.name).toLower());
    std::vector<std::pair<QString, QString>> lines;
    lines.emplace_back(QStringLiteral("Building type"), QStringLiteral("%1 (tD %2 h, tN %3 h by default)")
                                                             .arg(qs(type.name), number(type.daytimeHours, 0),
                                                                  number(type.nightHours, 0)));
    lines.emplace_back(QStringLiteral("Daytime operating hours tD"), hours(e.daytimeHours, typeDefault));
    lines.emplace_back(QStringLiteral("Night-time operating hours tN"), hours(e.nightHours, typeDefault));
    lines.emplace_back(QStringLiteral("Constant illuminance factor Fc"),
                       factor(e.constantIlluminanceFactor, QStringLiteral("constant-illuminance control")));
    lines.emplace_back(QStringLiteral("Occupancy dependency factor Fo"), factor(e.occupancyFactor, QStringLiteral("occupancy control")));
    lines.emplace_back(QStringLiteral("Daylight dependency factor FD"), factor(e.daylightFactor, QStringLiteral("daylight control")));
    const QString quick = QStringLiteral("not given: %1 %2 \u00d7 A, the quick method's default (%3 kWh/a)");
    lines.emplace_back(QStringLiteral("Parasitic power of controls Ppc"),
                       e.controlParasiticWatts
                           ? QStringLiteral("%1 W per luminaire (given), on for 8760 \u2212 tD \u2212 tN h/a (%2 kWh/a)")
                                 .arg(number(*e.controlParasiticWatts, 2), number(e.controlParasiticKWh, 1))
                           : quick.arg(number(kDefaultControlParasiticKWhPerM2, 0), kPerM2Year,
                                       number(e.controlParasiticKWh, 1)));
    lines.emplace_back(
        QStringLiteral("Emergency charging power Pem"),
        e.emergencyChargingWatts
            ? QStringLiteral("%1 W per luminaire (given) for tem %2 (%3 kWh/a)")
                  .arg(number(*e.emergencyChargingWatts, 2),
                       hours(e.emergencyChargingHours, QStringLiteral("default: charging all year, Lucerna's assumption")),
                       number(e.emergencyParasiticKWh, 1))
            : quick.arg(number(kDefaultEmergencyParasiticKWhPerM2, 0), kPerM2Year, number(e.emergencyParasiticKWh, 1)));
    lines.emplace_back(QStringLiteral("Floor area A"),
                       QStringLiteral("%1 %2 (%3)").arg(number(e.areaM2.value, 1), kM2,
                                                       e.areaM2.given ? QStringLiteral("given")
                                                                      : QStringLiteral("the geometry's extent in plan")));
    return lines;
}

ReportTable powerTable(const SceneEnergy& s) {
    ReportTable t = tableOf({{QStringLiteral("Qty"), 0.5, Qt::AlignRight},
                             {QStringLiteral("Light"), 3.2},
                             {QStringLiteral("Circuit power Pn each [W]"), 1.2, Qt::AlignRight},
                             {QStringLiteral("Stated by"), 1.1},
                             {QStringLiteral("Pn [W]"), 0.9, Qt::AlignRight}});
    for (const EnergyLightType& type : s.types) {
        QString name = qs(type.kind);
        if (!type.product.empty()) name += QStringLiteral(": ") + qs(type.product);
        if (!type.file.empty()) name += QStringLiteral("\n") + qs(type.file);
        else name += QStringLiteral(" (%1%2)").arg(qs(type.names.front()),
                                                   type.names.size() > 1 ? QStringLiteral(" and %1 more").arg(type.names.size() - 1)
                                                                         : QString());
        const int count = int(type.names.size());
        t.rows.push_back({QString::number(count), name, number(type.wattsEach, 1),
                          type.fromFile ? QStringLiteral("the file") : QStringLiteral("circuit_watts"),
                          number(type.wattsEach * count, 1)});
    }
    t.rows.push_back({QString::number(s.energy->luminaires), QStringLiteral("Total"), QString(), QString(),
                      number(s.energy->installedWatts, 1)});
    t.boldRows = {int(t.rows.size()) - 1};
    return t;
}

}  // namespace

void addEnergySection(PageFlow& flow, const ReportData& data) {
    const SceneEnergy& s = data.energy;
    flow.heading(QStringLiteral("Lighting energy (LENI)"));
    flow.paragraph(QStringLiteral("The lighting energy numeric indicator of EN 15193-1:2017, Energy performance of "
                                  "buildings \u2014 Energy requirements for lighting \u2014 Part 1: Specifications, "
                                  "Module M9: LENI = (W_L + W_P) / A, with W_L = \u03a3 Pn Fc (tD Fo FD + tN Fo) / 1000 "
                                  "and W_P = \u03a3 (Ppc (8760 \u2212 tD \u2212 tN) + Pem tem) / 1000 over the "
                                  "luminaires switched on."),
                   flow.fonts().small);
    if (!s.energy) {
        QString why = QStringLiteral("LENI not computed: ") + qs(s.notComputed) + QStringLiteral(".");
        if (!s.withoutPower.empty()) {
            QStringList names;
            for (size_t i = 0; i < s.withoutPower.size() && i < 5; ++i) names << qs(s.withoutPower[i]);
            why += QStringLiteral(" Without power: %1%2.")
                       .arg(names.join(QStringLiteral(", ")),
                            s.withoutPower.size() > 5 ? QStringLiteral(" and %1 more").arg(s.withoutPower.size() - 5)
                                                      : QString());
        }
        flow.paragraph(why);
        return;
    }
    const LightingEnergy& e = *s.energy;
    flow.keyValues(factorLines(s), 0.38);
    flow.table(powerTable(s));
    flow.keyValues({{QStringLiteral("W_L (illumination)"), number(e.lightingKWh, 1) + QStringLiteral(" kWh/a")},
                    {QStringLiteral("W_P (parasitic)"),
                     QStringLiteral("%1 kWh/a (controls %2, emergency %3)")
                         .arg(number(e.parasiticKWh, 1), number(e.controlParasiticKWh, 1), number(e.emergencyParasiticKWh, 1))},
                    {QStringLiteral("A"), number(e.areaM2.value, 1) + QStringLiteral(" ") + kM2},
                    {QStringLiteral("LENI"), number(e.leni, 2) + QStringLiteral(" ") + kPerM2Year}},
                   0.38);
    QString note = QStringLiteral("Lights switched off are not counted.");
    if (s.emitterObjects > 0)
        note += QStringLiteral(" %1 emitting object(s) state no power and are not counted.").arg(s.emitterObjects);
    flow.paragraph(note, flow.fonts().small);
}

}  // namespace lucerna
