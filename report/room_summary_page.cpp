#include "report/report_pages.h"
#include "report/report_text.h"

#include <QLatin1String>

namespace lucerna {

namespace {

QString metres(double m) { return QString::number(m, 'f', 2) + QStringLiteral(" m"); }

QString maintenanceText(const MaintenanceRange& m, const std::optional<MaintenanceFactor>& sceneMaintenance) {
    if (!m.electric) return QStringLiteral("none: no electric light is switched on");
    if (!m.maintained()) return QStringLiteral("none: maintained values not checked (the figures are the new installation's)");
    QString text = m.lowest == m.highest ? QString::number(m.lowest, 'f', 2)
                                         : QStringLiteral("%1 to %2 (the lights' own factors)")
                                               .arg(QString::number(m.lowest, 'f', 2), QString::number(m.highest, 'f', 2));
    if (const auto& f = sceneMaintenance; f && !f->value) {
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

// The lights and their load, as the schedule counts them (over the extent in plan).
void addLoadFacts(std::vector<std::pair<QString, QString>>& facts, int luminaires, const std::optional<double>& watts,
                  int withoutWatts, double floorAreaM2) {
    facts.emplace_back(QStringLiteral("Luminaires"), QString::number(luminaires) +
                                                         QStringLiteral(" switched on (the schedule's lights)"));
    QString load = QStringLiteral("not stated (no light states its power)");
    if (watts) {
        load = QString::number(*watts, 'f', 1) + QStringLiteral(" W");
        if (withoutWatts > 0)
            load += QStringLiteral(" (%1 of %2 lights state no power: not counted)").arg(withoutWatts).arg(luminaires);
        else if (floorAreaM2 > 0)
            load += QStringLiteral(", %1 W/m\u00b2").arg(QString::number(*watts / floorAreaM2, 'f', 2));
    } else if (luminaires == 0) {
        load = QStringLiteral("none (no electric light)");
    }
    facts.emplace_back(QStringLiteral("Connected load"), load);
}

QString openingsText(const RoomEntry& e) {
    if (!e.drawn) return QStringLiteral("- (marked)");
    QStringList parts;
    const auto add = [&](int n, const char* one, const char* many) {
        if (n > 0) parts << QStringLiteral("%1 %2").arg(n).arg(QLatin1String(n == 1 ? one : many));
    };
    add(e.windows, "window", "windows");
    add(e.doors, "door", "doors");
    add(e.plainOpenings, "opening", "openings");
    if (parts.isEmpty()) return QStringLiteral("none");
    return parts.join(QStringLiteral(", ")) + QStringLiteral(" (%1 m\u00b2)").arg(QString::number(e.openingAreaM2, 'f', 1));
}

QString roomMaintenanceText(const RoomEntry& e) {
    const MaintenanceRange& m = e.maintenance;
    QString text = !m.electric       ? QStringLiteral("none (no electric light)")
                   : !m.maintained() ? QStringLiteral("none (new installation)")
                   : m.lowest == m.highest
                       ? QString::number(m.lowest, 'f', 2)
                       : QStringLiteral("%1 to %2").arg(QString::number(m.lowest, 'f', 2), QString::number(m.highest, 'f', 2));
    if (e.lightsInside > 0) text += QStringLiteral(" (%1 light%2)").arg(e.lightsInside).arg(e.lightsInside == 1 ? "" : "s");
    else if (m.electric) text += QStringLiteral(" (no light inside: the scene's)");
    return text;
}

QString reflectanceText(const RoomEntry& e, size_t k) {
    return e.reflectances[k] ? QString::number(100 * *e.reflectances[k], 'f', 0) + QStringLiteral("%") : QStringLiteral("-");
}

// Eavg with its error bar, and U0 with its, of a wall or ceiling figure ("-" where not computed).
std::pair<QString, QString> illuminanceText(const std::optional<SurfaceIlluminance>& s) {
    if (!s) return {QStringLiteral("not computed"), QStringLiteral("-")};
    if (s->grid.counted == 0) return {QStringLiteral("no point"), QStringLiteral("-")};
    QString e = lux(s->grid.average), u = QString::number(s->grid.uniformity, 'f', 2);
    if (s->errors) {
        e += QStringLiteral(" \u00b1 ") + lux(s->errors->average);
        u += QStringLiteral(" \u00b1 ") + QString::number(s->errors->uniformity, 'f', 2);
    }
    return {e, u};
}

void addRoomsPage(PageFlow& flow, const ReportData& data) {
    const RoomsSummary& r = *data.rooms;
    flow.newPage();
    flow.heading(QStringLiteral("Room summary"));
    std::vector<std::pair<QString, QString>> facts;
    facts.emplace_back(QStringLiteral("Rooms"), QString::number(r.rooms.size()));
    facts.emplace_back(QStringLiteral("Maintenance factor"), maintenanceText(maintenanceRange(*data.scene), data.scene->maintenance));
    const Schedule& s = data.schedule;
    addLoadFacts(facts, s.luminaires, s.totalWatts, s.withoutWatts, s.floorAreaM2);
    flow.keyValues(facts, 0.25);

    ReportTable dims = tableOf({{QStringLiteral("Room"), 1.2},
                                {QStringLiteral("Floor area [m\u00b2]"), 0.9, Qt::AlignRight},
                                {QStringLiteral("Outline, x by z [m]"), 1.1, Qt::AlignRight},
                                {QStringLiteral("Height [m]"), 0.7, Qt::AlignRight},
                                {QStringLiteral("Openings"), 1.7},
                                {QStringLiteral("Maintenance factor"), 1.3}});
    ReportTable surfaces = tableOf({{QStringLiteral("Room"), 1.2},
                                    {QStringLiteral("Surface"), 0.8},
                                    {QStringLiteral("Material"), 1.6},
                                    {QStringLiteral("Reflectance"), 0.9, Qt::AlignRight},
                                    {QStringLiteral("Eavg [lx]"), 1.1, Qt::AlignRight},
                                    {QStringLiteral("U0"), 1.0, Qt::AlignRight}});
    for (const RoomEntry& e : r.rooms) {
        const QString name = qs(e.name) + (e.drawn ? QString() : QStringLiteral(" (marked)"));
        dims.rows.push_back({name, QString::number(e.floorAreaM2, 'f', 1),
                             QStringLiteral("%1 x %2").arg(QString::number(e.widthM, 'f', 2), QString::number(e.depthM, 'f', 2)),
                             QString::number(e.heightM, 'f', 2), openingsText(e), roomMaintenanceText(e)});
        const char* roles[3] = {"Floor", "Walls", "Ceiling"};
        const std::optional<SurfaceIlluminance>* lit[3] = {nullptr, &e.walls, &e.ceiling};
        for (size_t k = 0; k < 3; ++k) {
            const auto [lx, u0] = lit[k] ? illuminanceText(*lit[k]) : std::pair(QStringLiteral("-"), QStringLiteral("-"));
            surfaces.rows.push_back({k == 0 ? name : QString(), QLatin1String(roles[k]),
                                     e.materials[k].empty() ? QStringLiteral("-") : qs(e.materials[k]),
                                     reflectanceText(e, k), lx, u0});
        }
    }
    flow.subheading(QStringLiteral("Dimensions, openings and maintenance"));
    flow.table(dims);
    flow.paragraph(QStringLiteral("A drawn room's floor area is its outline's; a marked room's, its faces at the bottom "
                                  "of its shell, and its extent that of its surfaces. The maintenance factor is that of "
                                  "the lights switched on inside the room (in plan and between floor and ceiling)."),
                   flow.fonts().small);
    flow.subheading(QStringLiteral("Reflectances and the illuminance of walls and ceiling"));
    flow.table(surfaces);
    flow.paragraph(QStringLiteral("Reflectance: the material's diffuse albedo weighted by luminance (0.2126 R + 0.7152 "
                                  "G + 0.0722 B), of a drawn room's own materials, of a marked room's the material of "
                                  "the largest area among its faces facing that way. Eavg and U0 of the walls and the "
                                  "ceiling (EN 12464-1:2021) with their 95% error bars, where a task area in the room "
                                  "asks for them (the method page says how); the floor's are the task areas' pages'."),
                   flow.fonts().small);
}

}  // namespace

void addRoomSummaryPage(PageFlow& flow, const ReportData& data) {
    if (data.rooms) addRoomsPage(flow, data);
    if (!data.room) return;
    const RoomSummary& r = *data.room;
    flow.newPage();
    flow.heading(QStringLiteral("Room summary"));
    std::vector<std::pair<QString, QString>> facts;
    facts.emplace_back(QStringLiteral("Dimensions"), QStringLiteral("%1 x %2, %3 high (the geometry's extent: x by z in "
                                                                    "plan, y up)")
                                                         .arg(metres(r.widthM), metres(r.depthM), metres(r.heightM)));
    facts.emplace_back(QStringLiteral("Floor area"), QString::number(r.floorAreaM2, 'f', 1) + QStringLiteral(" m\u00b2"));
    facts.emplace_back(QStringLiteral("Maintenance factor"), maintenanceText(r.maintenance, r.sceneMaintenance));
    addLoadFacts(facts, r.luminaires, r.connectedLoadW, r.withoutWatts, r.floorAreaM2);
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
