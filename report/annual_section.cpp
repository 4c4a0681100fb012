// An area's year of daylight in the report (SPEC.md section 6): the weather file, the method and
// its stated error, DA300 on the plan, and the metrics with EN 17037's levels.

#include "report/report_pages.h"
#include "report/report_text.h"

namespace lucerna {

namespace {

QString percent(double fraction) { return QString::asprintf("%.1f%%", 100 * fraction); }

ReportTable metricsTable(const AnnualMetrics& m) {
    ReportTable t = tableOf({{QStringLiteral("Metric"), 2.2}, {QStringLiteral("Value"), 1.0, Qt::AlignRight},
                             {QStringLiteral("What it counts"), 3.2}});
    t.rows.push_back({QStringLiteral("sDA300/50%"), QString::asprintf("%.1f%%", m.sda300),
                      QStringLiteral("points with 300 lx in at least half of the occupied hours (no blinds)")});
    t.rows.push_back({QStringLiteral("ASE1000,250h"), QString::asprintf("%.1f%%", m.ase),
                      QStringLiteral("points with direct sun over 1000 lx in more than 250 occupied hours")});
    t.rows.push_back({QStringLiteral("UDI fell short"), percent(m.udiFellShort), QStringLiteral("occupied hours under 100 lx")});
    t.rows.push_back({QStringLiteral("UDI useful"), percent(m.udiUseful), QStringLiteral("occupied hours from 100 to 3000 lx")});
    t.rows.push_back({QStringLiteral("UDI exceeded"), percent(m.udiExceeded), QStringLiteral("occupied hours over 3000 lx")});
    return t;
}

ReportTable en17037Table(const AnnualMetrics& m) {
    ReportTable t = tableOf({{QStringLiteral("EN 17037 level"), 1.4}, {QStringLiteral("Hours with E_T on half"), 1.4, Qt::AlignRight},
                             {QStringLiteral("Hours with E_TM on 95%"), 1.4, Qt::AlignRight}, {QStringLiteral("Outcome"), 0.9}});
    for (const En17037Level& l : m.en17037)
        t.rows.push_back({QStringLiteral("%1 (%2 / %3 lx)").arg(qs(l.name)).arg(l.targetLux).arg(l.minimumTargetLux),
                          percent(l.fractionTarget), percent(l.fractionMinimum),
                          l.met ? QStringLiteral("met") : QStringLiteral("not met")});
    return t;
}

}  // namespace

void addAnnualDaylight(PageFlow& flow, const ReportData& data, const AreaReport& a) {
    const AnnualReport& y = *a.annual;
    const WeatherFile& w = *data.settings.weather;
    const Occupancy& o = data.settings.occupancy;
    flow.ensure(flow.pageHeight() * 0.6);
    flow.subheading(QStringLiteral("Annual daylight: %1").arg(qs(a.name)));
    flow.paragraph(QStringLiteral("Weather file %1: %2. %3 hours with daylight; occupied from %4:00 to %5:00 local "
                                  "standard time (%6 hours), electric light off.")
                       .arg(qs(data.settings.weatherPath), qs(w.describe()))
                       .arg(y.daylightHours)
                       .arg(o.fromHour)
                       .arg(o.toHour)
                       .arg(y.metrics.occupiedHours),
                   flow.fonts().small);
    flow.paragraph(QStringLiteral("Method: the Perez all-weather sky of each hour and daylight coefficients (the sky in "
                                  "2,305 patches, the sun's reflections at the nodes of its path, its direct light traced "
                                  "each hour through its disc). Stated 95% error of an hour's value: %1 statistical "
                                  "(median over the values), %2 from the discretisation of the sky and the sun.")
                       .arg(percent(y.statisticalRelative), percent(y.discretisationRelative)),
                   flow.fonts().small);
    PlanValues plan;
    plan.values = y.da300Percent;
    plan.insideGeometry = y.insideGeometry;
    plan.statistics = gridStatistics(y.da300Percent, y.insideGeometry);
    plan.quantity = QStringLiteral("DA300 [%]");
    addPlan(flow, data, a, std::move(plan), flow.mm(90));
    flow.table(metricsTable(y.metrics));
    flow.table(en17037Table(y.metrics));
}

}  // namespace lucerna
