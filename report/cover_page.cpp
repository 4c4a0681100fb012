#include "report/report_pages.h"
#include "report/report_text.h"

#include "render/display/display.h"

#include <QPainter>

#include <algorithm>

namespace lucerna {

void addPicture(PageFlow& flow, const QImage& picture, double maxHeight) {
    if (picture.isNull()) return;
    const double aspect = double(picture.height()) / double(picture.width());
    const double height = std::min(maxHeight, flow.width() * aspect);
    flow.figure(height, [picture](QPainter& p, const QRectF& r) {
        const double w = r.height() / (double(picture.height()) / double(picture.width()));
        const QRectF at(r.left() + (r.width() - w) / 2, r.top(), w, r.height());
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.drawImage(at, picture);
    });
}

namespace {

// One row per area: what it asks and what it achieves.
ReportTable summaryTable(const ReportData& data) {
    std::vector<ReportColumn> columns{{QStringLiteral("Task area"), 1.3}, {QStringLiteral("Activity (EN 12464-1)"), 2.2},
                                      {QStringLiteral("Eavg [lx]"), 0.8, Qt::AlignRight}, {QStringLiteral("U0"), 0.6, Qt::AlignRight},
                                      {QStringLiteral("UGR"), 0.6, Qt::AlignRight}, {QStringLiteral("Requirements"), 1.5}};
    const bool daylight = std::any_of(data.areas.begin(), data.areas.end(), [](const AreaReport& a) { return a.daylightFactor.has_value(); });
    if (daylight) columns.insert(columns.begin() + 5, {QStringLiteral("DFavg"), 0.7, Qt::AlignRight});
    ReportTable t = tableOf(columns);
    for (const AreaReport& a : data.areas) {
        QString outcome = QStringLiteral("none given");
        if (a.requirement) {
            // The area's own checks and its zones', as its checks page lists them.
            std::vector<const RequirementCheck*> checks;
            for (const RequirementCheck& c : a.checks) checks.push_back(&c);
            for (const ZoneReport& z : a.zones)
                for (const RequirementCheck& c : z.checks) checks.push_back(&c);
            int met = 0, notMet = 0, borderline = 0, open = 0;
            for (const RequirementCheck* check : checks) {
                const RequirementCheck& c = *check;
                if (c.outcome == CheckOutcome::Met) ++met;
                else if (c.outcome == CheckOutcome::NotMet) ++notMet;
                else if (c.outcome == CheckOutcome::Borderline) ++borderline;
                else ++open;  // not stated, not computed, not checked
            }
            outcome = notMet > 0 ? QStringLiteral("%1 of %2 not met").arg(notMet).arg(checks.size())
                                 : QStringLiteral("%1 of %2 met").arg(met).arg(checks.size());
            if (borderline > 0) outcome += QStringLiteral(", %1 borderline").arg(borderline);
            if (open > 0) outcome += QStringLiteral(", %1 open").arg(open);
        }
        const QString activity = a.requirement ? activityText(*a.requirement) : QStringLiteral("none given");
        const bool any = a.statistics.counted > 0;
        QStringList row{qs(a.name), activity, any ? lux(a.statistics.average) : QStringLiteral("-"),
                        any ? QString::asprintf("%.3f", a.statistics.uniformity) : QStringLiteral("-"),
                        a.worstUgr ? QString::asprintf("%.1f", *a.worstUgr) : QStringLiteral("-"), outcome};
        if (daylight) {
            const bool df = a.daylightFactor && a.daylightFactor->statistics.counted > 0;
            row.insert(5, df ? QString::asprintf("%.2f%%", a.daylightFactor->statistics.average) : QStringLiteral("-"));
        }
        t.rows.push_back(row);
    }
    return t;
}

}  // namespace

void addCoverPage(PageFlow& flow, const ReportData& data) {
    flow.space(flow.mm(18));
    flow.title(qs(data.projectName), flow.fonts().title);
    flow.space(flow.mm(2));
    flow.title(QStringLiteral("Lighting design report"), flow.fonts().subtitle);
    flow.space(flow.mm(8));
    std::vector<std::pair<QString, QString>> facts;
    if (!data.client.empty()) facts.emplace_back(QStringLiteral("Client"), qs(data.client));
    if (!data.designer.empty()) facts.emplace_back(QStringLiteral("Designer"), qs(data.designer));
    facts.emplace_back(QStringLiteral("Date"), qs(data.date));
    facts.emplace_back(QStringLiteral("Scene"), qs(data.sceneFile));
    facts.emplace_back(QStringLiteral("Values"), qs(data.maintenance));
    facts.emplace_back(QStringLiteral("Calculated with"), qs(data.software));
    flow.keyValues(facts, 0.25);
    if (!data.notes.empty()) {
        flow.subheading(QStringLiteral("Notes"));
        flow.paragraph(qs(data.notes));
    }
    if (data.renders && data.renders->converged.width > 0) {
        flow.space(flow.mm(3));
        addPicture(flow, toDisplayImage(data.renders->converged, data.renders->exposureStops), flow.mm(80));
    }
    flow.subheading(QStringLiteral("Summary"));
    flow.table(summaryTable(data));
    QString about = QStringLiteral("Eavg, U0 and UGR are the calculated values of each task area; the requirements "
                                   "are EN 12464-1's for its activity (Em, U0, UGR and Ra), checked on the area's page.");
    if (std::any_of(data.areas.begin(), data.areas.end(), [](const AreaReport& a) { return a.daylightFactor.has_value(); }))
        about += QStringLiteral(" DFavg: the average daylight factor under the CIE overcast sky, with EN 17037's "
                                "daylight provision on the area's page.");
    flow.paragraph(about, flow.fonts().small);
}

}  // namespace lucerna
