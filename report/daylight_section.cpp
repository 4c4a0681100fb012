#include "report/report_pages.h"
#include "report/report_text.h"
#include "render/photometry/grid_text.h"

namespace lucerna {

namespace {

QString percent(double x) { return QString::asprintf("%.2f%%", x); }

ReportTable provisionTable(const DaylightProvision& p) {
    ReportTable t = tableOf({{QStringLiteral("EN 17037 level"), 1.2}, {QStringLiteral("DF on half the plane"), 1.2, Qt::AlignRight},
                             {QStringLiteral("Target"), 0.9, Qt::AlignRight}, {QStringLiteral("DF on 95% of it"), 1.2, Qt::AlignRight},
                             {QStringLiteral("Target"), 0.9, Qt::AlignRight}, {QStringLiteral("Outcome"), 0.9}});
    for (const ProvisionLevel& l : p.levels)
        t.rows.push_back({QStringLiteral("%1 (%2 / %3 lx)").arg(l.name).arg(l.targetLux).arg(l.minimumTargetLux),
                          percent(p.dfHalf), QStringLiteral("\u2265 ") + percent(l.targetDf), percent(p.df95),
                          QStringLiteral("\u2265 ") + percent(l.minimumTargetDf),
                          l.met ? QStringLiteral("met") : QStringLiteral("not met")});
    return t;
}

}  // namespace

void addDaylightFactor(PageFlow& flow, const ReportData& data, const AreaReport& a) {
    const DaylightFactorReport& df = *a.daylightFactor;
    flow.ensure(flow.pageHeight() * 0.6);
    flow.subheading(QStringLiteral("Daylight factor: %1").arg(qs(a.name)));
    flow.paragraph(QStringLiteral("The CIE overcast sky alone (Eh,sky %1 lx on an open horizontal plane), the sun and "
                                  "every electric light off: DF = 100 E / Eh,sky at each point of the area's grid.")
                       .arg(QString::number(df.skyHorizontalIlluminance, 'f', 1)),
                   flow.fonts().small);
    if (df.statistics.counted == 0) {
        flow.paragraph(qs(daylightFactorFiguresLine(df.statistics)));
        return;
    }
    PlanValues plan;
    plan.values = df.percent;
    plan.insideGeometry = df.result.insideGeometry;
    plan.statistics = df.statistics;
    plan.quantity = QStringLiteral("DF [%]");
    addPlan(flow, data, a, std::move(plan), flow.mm(95));
    const GridStatistics& s = df.statistics;
    flow.paragraph(qs(daylightFactorFiguresLine(s)), flow.fonts().tableBold);
    for (const std::string& line : gridErrorLines(df.result, s.counted)) flow.paragraph(qs(line), flow.fonts().small);
    flow.table(provisionTable(df.provision));
    flow.paragraph(QStringLiteral("Median external diffuse illuminance %1 lx%2. EN 17037 asks for its reference plane "
                                  "0.85 m above the floor; this area's plane is the one shown.")
                       .arg(QString::number(df.medianDiffuseIlluminance, 'f', 0),
                            df.medianGiven ? QString() : QStringLiteral(" (the site gives none: EN 17037's usual value)")),
                   flow.fonts().small);
}

}  // namespace lucerna
