#include "report/report_pages.h"
#include "report/report_text.h"

namespace lucerna {

namespace {

QString metres(double m) { return QString::number(m, 'f', 2) + QStringLiteral(" m"); }

QString maintenanceText(const RoomSummary& r) {
    const MaintenanceRange& m = r.maintenance;
    if (!m.electric) return QStringLiteral("none: no electric light is switched on");
    if (!m.maintained()) return QStringLiteral("none: maintained values not checked (the figures are the new installation's)");
    QString text = m.lowest == m.highest ? QString::number(m.lowest, 'f', 2)
                                         : QStringLiteral("%1 to %2 (the lights' own factors)")
                                               .arg(QString::number(m.lowest, 'f', 2), QString::number(m.highest, 'f', 2));
    if (const auto& f = r.sceneMaintenance; f && !f->value) {
        QStringList parts;
        const auto part = [&](const char* name, const std::optional<double>& x) {
            if (x) parts << QStringLiteral("%1 %2").arg(QLatin1String(name), QString::number(*x, 'f', 2));
        };
        part("LLMF", f->lampLumenMaintenance);
        part("LSF", f->lampSurvival);
        part("LMF", f->luminaireMaintenance);
        part("RSMF", f->roomSurfaceMaintenance);
        text += QStringLiteral(" (CIE 97: %1)").arg(parts.join(QStringLiteral(" x ")));
    }
    return text;
}

ReportTable surfacesTable(const RoomSummary& r) {
    ReportTable t = tableOf({{QStringLiteral("Surface"), 0.9},
                             {QStringLiteral("Material"), 1.8},
                             {QStringLiteral("Reflectance"), 1.0, Qt::AlignRight},
                             {QStringLiteral("Its area [m\u00b2]"), 1.0, Qt::AlignRight},
                             {QStringLiteral("Of all facing that way"), 1.4, Qt::AlignRight}});
    for (const MainSurface& s : r.surfaces) {
        if (s.material.empty()) {
            t.rows.push_back({qs(s.role), QStringLiteral("- (no face)"), QStringLiteral("-"), QStringLiteral("-"), QStringLiteral("-")});
            continue;
        }
        t.rows.push_back({qs(s.role), qs(s.material), QString::number(100 * s.reflectance, 'f', 0) + QStringLiteral("%"),
                          QString::number(s.areaM2, 'f', 1),
                          QString::number(100 * s.areaM2 / s.facingAreaM2, 'f', 0) + QStringLiteral("%")});
    }
    return t;
}

}  // namespace

void addRoomSummaryPage(PageFlow& flow, const ReportData& data) {
    if (!data.room) return;
    const RoomSummary& r = *data.room;
    flow.newPage();
    flow.heading(QStringLiteral("Room summary"));
    std::vector<std::pair<QString, QString>> facts;
    facts.emplace_back(QStringLiteral("Dimensions"), QStringLiteral("%1 x %2, %3 high (the geometry's extent: x by z in "
                                                                    "plan, y up)")
                                                         .arg(metres(r.widthM), metres(r.depthM), metres(r.heightM)));
    facts.emplace_back(QStringLiteral("Floor area"), QString::number(r.floorAreaM2, 'f', 1) + QStringLiteral(" m\u00b2"));
    facts.emplace_back(QStringLiteral("Maintenance factor"), maintenanceText(r));
    facts.emplace_back(QStringLiteral("Luminaires"), QString::number(r.luminaires) +
                                                         QStringLiteral(" switched on (the schedule's lights)"));
    QString load = QStringLiteral("not stated (no light states its power)");
    if (r.connectedLoadW) {
        load = QString::number(*r.connectedLoadW, 'f', 1) + QStringLiteral(" W");
        if (r.withoutWatts > 0)
            load += QStringLiteral(" (%1 of %2 lights state no power: not counted)").arg(r.withoutWatts).arg(r.luminaires);
        else if (r.floorAreaM2 > 0)
            load += QStringLiteral(", %1 W/m\u00b2").arg(QString::number(*r.connectedLoadW / r.floorAreaM2, 'f', 2));
    } else if (r.luminaires == 0) {
        load = QStringLiteral("none (no electric light)");
    }
    facts.emplace_back(QStringLiteral("Connected load"), load);
    flow.keyValues(facts, 0.25);

    flow.subheading(QStringLiteral("Reflectances of the main surfaces"));
    flow.table(surfacesTable(r));
    flow.paragraph(QStringLiteral("Each main surface is the material of the largest area among the faces facing that "
                                  "way (the floor up, the walls sideways, the ceiling down; within 45 degrees of "
                                  "vertical counts as up or down), of the materials with a diffuse part. Reflectance: "
                                  "the material's diffuse albedo weighted by luminance (0.2126 R + 0.7152 G + 0.0722 "
                                  "B)."),
                   flow.fonts().small);
}

}  // namespace lucerna
