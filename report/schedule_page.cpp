#include "report/report_pages.h"
#include "report/report_text.h"

#include <algorithm>

namespace lucerna {

namespace {

QString number(double x, int decimals) { return QString::number(x, 'f', decimals); }

// "a, b, c" or "a, b and 5 more": which lights of the scene a line counts.
QString lightNames(const std::vector<std::string>& names) {
    QStringList shown;
    for (size_t i = 0; i < names.size() && i < 3; ++i) shown << qs(names[i]);
    QString text = shown.join(QStringLiteral(", "));
    if (names.size() > 3) text += QStringLiteral(" and %1 more").arg(names.size() - 3);
    return text;
}

ReportTable scheduleTable(const Schedule& s) {
    ReportTable t;
    t.header = {QStringLiteral("Qty"),          QStringLiteral("Luminaire"), QStringLiteral("Flux each [lm]"),
                QStringLiteral("Power each [W]"), QStringLiteral("Ra"),      QStringLiteral("CCT [K]"),
                QStringLiteral("MF"),           QStringLiteral("Flux [lm]"), QStringLiteral("Power [W]")};
    t.weights = {0.5, 3.0, 0.95, 0.95, 0.5, 0.7, 0.55, 0.95, 0.9};
    t.alignment = {Qt::AlignRight, Qt::AlignLeft,  Qt::AlignRight, Qt::AlignRight, Qt::AlignRight,
                   Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
    for (const ScheduleEntry& e : s.entries) {
        QString name = qs(e.kind);
        if (!e.product.empty()) name += QStringLiteral(": ") + qs(e.product);
        if (!e.file.empty()) name += QStringLiteral("\n") + qs(e.file);
        else if (!e.names.empty()) name += QStringLiteral(" (%1)").arg(lightNames(e.names));
        const QString dash = QStringLiteral("-");
        t.rows.push_back({QString::number(e.count), name, number(e.lumensEach, 0),
                          e.wattsEach ? number(*e.wattsEach, 1) : dash,
                          e.colourRenderingIndex ? number(*e.colourRenderingIndex, 0) : dash,
                          e.temperatureK ? number(*e.temperatureK, 0) : dash, number(e.maintenanceFactor, 2),
                          number(e.lumensEach * e.count, 0), e.wattsEach ? number(*e.wattsEach * e.count, 1) : dash});
    }
    t.rows.push_back({QString::number(s.luminaires), QStringLiteral("Total"), QString(), QString(), QString(), QString(),
                      QString(), number(s.totalLumens, 0), s.totalWatts ? number(*s.totalWatts, 1) : QStringLiteral("-")});
    t.boldRows = {int(t.rows.size()) - 1};
    return t;
}

}  // namespace

void addSchedulePage(PageFlow& flow, const ReportData& data) {
    flow.newPage();
    const Schedule& s = data.schedule;
    flow.heading(s.daylight.empty() ? QStringLiteral("Luminaire schedule") : QStringLiteral("Luminaire schedule and daylight"));
    if (s.entries.empty()) {
        flow.paragraph(QStringLiteral("No electric lighting is switched on in this scene."));
    } else {
        flow.table(scheduleTable(s));
        flow.paragraph(QStringLiteral("Flux as installed (new); the figures on the task areas' pages are %1. Power: "
                                      "the light's circuit power where the scene gives it, else as the photometric "
                                      "file states it (not scaled when the scene overrides its flux); Ra as the file "
                                      "states it; \"-\": not stated.")
                           .arg(qs(data.maintenance)),
                       flow.fonts().small);
    }
    std::vector<std::pair<QString, QString>> load;
    if (s.totalWatts) {
        QString watts = QString::number(*s.totalWatts, 'f', 1) + QStringLiteral(" W");
        if (s.withoutWatts > 0)
            watts += QStringLiteral(" (%1 of %2 lights state no power: not counted)").arg(s.withoutWatts).arg(s.luminaires);
        load.emplace_back(QStringLiteral("Connected load"), watts);
    } else if (s.luminaires > 0) {
        load.emplace_back(QStringLiteral("Connected load"), QStringLiteral("not stated (no file states its power)"));
    }
    if (s.totalWatts && s.withoutWatts == 0 && *s.totalWatts > 0)
        load.emplace_back(QStringLiteral("Luminaire efficacy"),
                          QString::number(s.totalLumens / *s.totalWatts, 'f', 1) + QStringLiteral(" lm/W"));
    load.emplace_back(QStringLiteral("Floor area"), QString::number(s.floorAreaM2, 'f', 1) +
                                                       QStringLiteral(" m\u00b2 (the geometry's extent in plan)"));
    if (s.wattsPerM2)
        load.emplace_back(QStringLiteral("Specific connected load"),
                          QString::number(*s.wattsPerM2, 'f', 2) + QStringLiteral(" W/m\u00b2"));
    if (s.switchedOff > 0)
        load.emplace_back(QStringLiteral("Switched off"),
                          QStringLiteral("%1 light(s) of the scene, not counted and not lit").arg(s.switchedOff));
    flow.keyValues(load);
    const bool withoutFile = std::any_of(s.entries.begin(), s.entries.end(), [](const ScheduleEntry& e) { return e.file.empty(); });
    if (withoutFile)
        flow.paragraph(QStringLiteral("Point and spot lights and emitting objects have no photometric file: no data sheet."),
                       flow.fonts().small);
    if (!s.daylight.empty()) {
        flow.subheading(QStringLiteral("Daylight"));
        for (const std::string& line : s.daylight) flow.paragraph(qs(line));
    }
}

}  // namespace lucerna
