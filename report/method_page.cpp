#include "report/report_pages.h"
#include "report/report_text.h"
#include "core/number_format.h"

#include <algorithm>

namespace lucerna {

namespace {

// The settings as `lucerna grid` takes them.
QString gridOptions(const ReportSettings& s) {
    const GridSettings& g = s.grid;
    QString o = QStringLiteral(" --method %1 --error %2 --seed %3")
                    .arg(g.autoMethod ? QStringLiteral("auto") : QString(gridMethodName(g.method)))
                    .arg(QString::number(g.targetRelativeError, 'g', 6))
                    .arg(g.seed);
    if (g.samplesPerPass > 0) o += QStringLiteral(" --samples %1").arg(g.samplesPerPass);
    if (g.timeLimitSeconds > 0) o += QStringLiteral(" --time %1").arg(QString::number(g.timeLimitSeconds, 'g', 6));
    return o;
}

// The command that computes an area's grid alone, with the same figures.
QString gridCommand(const ReportData& data, const AreaReport& a) {
    const QString scene = qs(data.sceneFile);
    const QString where = a.defaultWorkPlane ? QStringLiteral(" --work-plane 0.8")
                                             : QStringLiteral(" --task-area \"%1\"").arg(qs(a.name));
    return QStringLiteral("lucerna grid %1%2%3").arg(scene, where, gridOptions(data.settings));
}

}  // namespace

void addMethodPage(PageFlow& flow, const ReportData& data) {
    flow.newPage();
    flow.heading(QStringLiteral("Calculation method and error bars"));
    const ReportSettings& s = data.settings;
    const GridMethod method = data.areas.empty() ? s.grid.method : data.areas.front().result.method;

    flow.subheading(QStringLiteral("Illuminance"));
    flow.paragraph(QStringLiteral("Each task area is a calculation grid: points at the centres of equal cells, EN "
                                  "12464-1's spacing p = 0.2 x 5^log10(d) m (d the longer side) unless the area gives "
                                  "one. The illuminance is that on the side the grid faces, of the direct and the "
                                  "interreflected light, computed by %1. A point's error bar is the half-width of its "
                                  "95% confidence interval; the calculation stops when every point's error bar is "
                                  "within the target fraction of its value, or at the time limit. Points inside "
                                  "geometry are left out of Eavg, Emin, Emax and U0.")
                       .arg(methodDescription(method)));
    std::vector<std::pair<QString, QString>> settings;
    settings.emplace_back(QStringLiteral("Method"), s.grid.autoMethod ? QStringLiteral("auto (bdpt where a lamp reaches a "
                                                                                       "point only through glass, else path)")
                                                                      : QString(gridMethodName(s.grid.method)));
    settings.emplace_back(QStringLiteral("Target error bar"),
                          QStringLiteral("%1% of each point's value (95%)").arg(QString::number(100 * s.grid.targetRelativeError, 'g', 4)));
    settings.emplace_back(QStringLiteral("Time limit"), s.grid.timeLimitSeconds > 0
                                                            ? qs(formatDuration(s.grid.timeLimitSeconds)) + QStringLiteral(" per area")
                                                            : QStringLiteral("none"));
    settings.emplace_back(QStringLiteral("Seed"), QString::number(s.grid.seed));
    settings.emplace_back(QStringLiteral("Samples per pass"), s.grid.samplesPerPass > 0 ? QString::number(s.grid.samplesPerPass)
                                                                                        : QStringLiteral("the method's default"));
    flow.keyValues(settings, 0.25);

    ReportTable t;
    t.header = {QStringLiteral("Task area"), QStringLiteral("Method"), QStringLiteral("Passes"),
                QStringLiteral("Samples per point"), QStringLiteral("Time"), QStringLiteral("Largest error bar"),
                QStringLiteral("Target")};
    t.weights = {1.6, 0.8, 0.7, 1.1, 0.9, 1.1, 0.9};
    t.alignment = {Qt::AlignLeft, Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignLeft};
    for (const AreaReport& a : data.areas)
        t.rows.push_back({qs(a.name), QString(gridMethodName(a.result.method)), QString::number(a.result.passes),
                          QString::number(a.result.samplesPerPoint), qs(formatDuration(a.result.seconds)),
                          a.result.errorBarUnknown ? QStringLiteral("unknown")
                                                   : QString::asprintf("%.2f%%", 100 * a.result.maxRelativeError),
                          a.result.converged ? QStringLiteral("reached") : QStringLiteral("not reached")});
    flow.table(t);
    flow.paragraph(QStringLiteral("The largest error bar is relative to the point's value (or to a thousandth of "
                                  "Eavg, for points near 0 lx). Each area's figures are those the command line "
                                  "prints for the same scene and settings:"),
                   flow.fonts().small);
    for (const AreaReport& a : data.areas) flow.paragraph(gridCommand(data, a), flow.fonts().figure, flow.mm(4));

    if (std::any_of(data.areas.begin(), data.areas.end(), [](const AreaReport& a) { return !a.glare.empty(); })) {
        flow.subheading(QStringLiteral("Glare"));
        flow.paragraph(QStringLiteral(
            "UGR = 8 log10(0.25 / Lb x sum of L\u00b2 \u03c9 / p\u00b2) (CIE 117): for each observer, every luminaire "
            "it sees with its luminance L over its luminous area, the solid angle \u03c9 that area fills and Guth's "
            "position index p; Lb, the background luminance at the eye, is computed by the grid's method with its own "
            "error bar, from which the UGR's \u00b1 follows. Computed for the new installation (no maintenance "
            "factor), as CIE 117 asks. The requirement check takes the worst observer's UGR."));
    }
    flow.subheading(QStringLiteral("Maintenance, standard and data"));
    flow.paragraph(QStringLiteral("The figures are %1. Requirements are EN 12464-1:2011's (tables 5.1 to 5.36, a "
                                  "selection): maintained illuminance Em on the area's average, uniformity U0 = Emin "
                                  "/ Eavg, UGR limit and colour rendering Ra; check a design against the edition in "
                                  "force. Luminaire data (flux, power, Ra, luminous area) are the photometric files'.")
                       .arg(qs(data.maintenance)));
    if (data.renders) {
        flow.subheading(QStringLiteral("Renders"));
        const QString stop = data.settings.renderRelmse > 0
                                 ? QStringLiteral("until its estimated relative error (relMSE) is at most %1, read every "
                                                  "8 passes from 16 on, or %2 passes at most: %3 samples per pixel")
                                       .arg(QString::number(data.settings.renderRelmse, 'g', 3))
                                       .arg(data.settings.renderSpp)
                                       .arg(QString::number(data.renders->samplesPerPixel, 'f', 0))
                                 : QStringLiteral("with %1 samples per pixel").arg(data.settings.renderSpp);
        flow.paragraph(QStringLiteral("The camera's view is rendered by %1 (chosen by auto: %2) %3; its estimated "
                                      "relative error comes from the film's two half-buffers and reads noise, not "
                                      "bias. The lux view divides that render's luminance by the reflectance of the "
                                      "surface each pixel sees.")
                           .arg(qs(data.renders->backend), qs(data.renders->autoReason), stop));
    }
    flow.paragraph(QStringLiteral("Calculated by %1 on %2 in %3.")
                       .arg(qs(data.software), qs(data.date), qs(formatDuration(data.seconds))),
                   flow.fonts().small);
}

}  // namespace lucerna
