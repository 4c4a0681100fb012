#include "report/report_pages.h"
#include "report/report_text.h"
#include "core/number_format.h"

#include <QLatin1String>

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
    // An unsaved scene has no file to name: the command then reads as a template.
    const QString scene = data.sceneFile == "untitled scene" ? QStringLiteral("SCENE.json") : qs(data.sceneFile);
    const QString where = a.defaultWorkPlane ? QStringLiteral(" --work-plane 0.8")
                                             : QStringLiteral(" --task-area \"%1\"").arg(qs(a.name));
    return QStringLiteral("lucerna grid %1%2%3").arg(scene, where, gridOptions(data.settings));
}

// One calculated grid's row: its points, spacing, passes, time and largest error bar.
QStringList gridRow(const QString& name, size_t points, const QString& spacing, const GridResult& r, double target) {
    return {name,
            QString::number(points),
            spacing,
            QString(gridMethodName(r.method)),
            QString::number(r.passes),
            qs(formatDuration(r.seconds)),
            r.errorBarUnknown ? QStringLiteral("unknown") : QString::asprintf("%.2f%%", 100 * r.maxRelativeError),
            QString::number(100 * target, 'g', 3) + QStringLiteral("%") +
                (r.converged ? QString() : QStringLiteral(" (not reached)"))};
}

QString spacingText(const GridLayout& l) {
    return l.spacingUMeters == l.spacingVMeters
               ? QString::number(l.spacingUMeters, 'g', 3)
               : QString::number(l.spacingUMeters, 'g', 3) + QStringLiteral(" x ") + QString::number(l.spacingVMeters, 'g', 3);
}

// The edition the requirements come from, with the activities its table lacks.
QString editionText(const ReportData& data) {
    const StandardEdition asked = lightingStandardOf(*data.scene);
    QStringList fallback;
    for (const AreaReport& a : data.areas)
        if (a.requirement && a.requirement->edition != asked && !fallback.contains(QLatin1String(a.requirement->reference)))
            fallback << QLatin1String(a.requirement->reference);
    QString text = QLatin1String(standardEditionName(asked));
    if (!fallback.isEmpty())
        text += QStringLiteral(" (fallback to %1 for %2: the 2021 table here lacks %3)")
                    .arg(QLatin1String(standardEditionName(StandardEdition::En12464_2011)), fallback.join(QStringLiteral(", ")),
                         fallback.size() == 1 ? QStringLiteral("it") : QStringLiteral("them"));
    return text;
}

// An error factor as the page states it ("2.5"; 0 means the grid's own: "1").
QString factorText(double factor) { return QString::number(factor > 0 ? factor : 1.0, 'g', 3); }

// How Ez, the walls and ceiling, and the zones were computed, and each of their grids.
void addExtrasMethod(PageFlow& flow, const ReportData& data) {
    const bool cylindrical = std::any_of(data.areas.begin(), data.areas.end(), [](const AreaReport& a) { return a.cylindrical.has_value(); });
    const bool zones = std::any_of(data.areas.begin(), data.areas.end(), [](const AreaReport& a) { return !a.zones.empty(); });
    if (!cylindrical && data.roomSurfaces.empty() && !zones) return;
    flow.subheading(QStringLiteral("Cylindrical illuminance, walls, ceiling and zones"));
    QStringList text;
    if (cylindrical)
        text << QStringLiteral("Ez (EN 12464-1:2021, 5.2.6) is the mean cylindrical illuminance: at each point the "
                               "illuminance on a vertical plane averaged over all azimuths, estimated by planes at random "
                               "azimuths (lamps without size exactly), by the grid's method and settings, its error "
                               "target %1 times the grid's (%2% of each point's value). Its grid is the task area's "
                               "rectangle and spacing, at 1.2 m above the floor of the area's room (below) for seated "
                               "work or 1.6 m for standing (the area's posture), facing up. Eavg, Emin and U0,z as for "
                               "the area.")
                    .arg(factorText(data.settings.cylindricalErrorFactor))
                    .arg(QString::number(100 * data.settings.grid.targetRelativeError *
                                             (data.settings.cylindricalErrorFactor > 0 ? data.settings.cylindricalErrorFactor : 1),
                                         'g', 3));
    if (!data.roomSurfaces.empty())
        text << QStringLiteral(
                    "The walls' and ceiling's illuminance (EN 12464-1:2021, 5.2.4) is computed in the box of the room "
                    "the area lies in: a drawn room's outline from floor to ceiling, a marked room's surfaces' bounds, "
                    "else the scene's bounds (its lowest point the floor), once per box however many areas lie in it. "
                    "Each of its four side faces and its top face gets a grid at EN 12464-1's spacing for that face "
                    "(p = 0.2 x 5^log10(d), d its longer side); each point is moved along the face's normal onto the "
                    "first opaque surface within %1 m (a wall, a reveal) and set just in front of it, facing into the "
                    "room. A point in a window (its ray crosses a glazing pane or meets glass) or where nothing opaque is "
                    "that near (an opening, or no wall there) is left out, as the standard asks for the walls' "
                    "surfaces, not their openings. The walls' Eavg weighs each point by its cell's area; U0 = Emin / Eavg. Their "
                    "error target is %2 times the grid's (%3% of each point's value): their requirements lie far "
                    "from what a lit room achieves, and their dark corners converge slowest; the error bars stated "
                    "are those reached.")
                    .arg(kSurfaceDepthMeters)
                    .arg(factorText(data.settings.roomSurfaceErrorFactor))
                    .arg(QString::number(100 * data.roomSurfaces.front().settings.targetRelativeError, 'g', 3));
    if (zones)
        text << QStringLiteral("The surrounding zone and background area (EN 12464-1, 4.3.2 and 4.3.3) are bands in the "
                               "area's plane around it, clipped to its room box, computed as one grid by the area's "
                               "settings; their requirements follow from the area's Em (table 1), U0 0.40 and 0.10.");
    for (const QString& t : text) flow.paragraph(t);

    ReportTable t = tableOf({{QStringLiteral("Grid"), 2.0},
                             {QStringLiteral("Points"), 0.7, Qt::AlignRight},
                             {QStringLiteral("Spacing [m]"), 0.9, Qt::AlignRight},
                             {QStringLiteral("Method"), 0.7},
                             {QStringLiteral("Passes"), 0.7, Qt::AlignRight},
                             {QStringLiteral("Time"), 0.8, Qt::AlignRight},
                             {QStringLiteral("Largest error bar"), 1.0, Qt::AlignRight},
                             {QStringLiteral("Target"), 1.0}});
    const double target = data.settings.grid.targetRelativeError;
    for (const AreaReport& a : data.areas) {
        if (a.cylindrical)
            t.rows.push_back(gridRow(qs(a.name) + QStringLiteral(": Ez"), a.cylindrical->layout.points.size(),
                                     spacingText(a.cylindrical->layout), a.cylindrical->result,
                                     target * (data.settings.cylindricalErrorFactor > 0 ? data.settings.cylindricalErrorFactor : 1)));
        if (!a.zones.empty()) {
            size_t points = 0;
            for (const ZoneReport& z : a.zones) points += z.grid.points.size();
            const ZoneReport& z = a.zones.front();
            if (points > 0)
                t.rows.push_back(gridRow(qs(a.name) + QStringLiteral(": zones"), points,
                                         QString::number(z.grid.spacingMeters, 'g', 3), z.result, target));
        }
    }
    for (const RoomSurfacesReport& r : data.roomSurfaces)
        for (size_t g = 0; g < r.result.grids.size() && g < r.result.results.size(); ++g)
            t.rows.push_back(gridRow(qs(r.room.description) + QStringLiteral(": ") + qs(r.result.grids[g].name),
                                     r.result.grids[g].points.size(), spacingText(r.result.grids[g].layout),
                                     r.result.results[g], r.settings.targetRelativeError));
    // The caption stays with its table.
    flow.ensure(std::min(flow.lineHeight(flow.fonts().small) + flow.tableHeight(t), flow.pageHeight()));
    flow.paragraph(QStringLiteral("Their grids, as the area's grids above:"), flow.fonts().small);
    flow.table(t);
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
    settings.emplace_back(QStringLiteral("Method"), s.grid.autoMethod ? QStringLiteral("auto (the method measured best in short "
                                                                                       "pilots on each grid)")
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
    addExtrasMethod(flow, data);
    flow.subheading(QStringLiteral("Maintenance, standard and data"));
    flow.paragraph(QStringLiteral("The figures are %1. Requirements are from %2, a selection of its tables: maintained "
                                  "illuminance Em on the area's average, uniformity U0 = Emin / Eavg, UGR limit and "
                                  "colour rendering Ra, and where the 2021 edition states them Ez, the walls' and the "
                                  "ceiling's Em with their U0; check a design against the edition in force. Luminaire "
                                  "data (flux, power, Ra, luminous area) are the photometric files'.")
                       .arg(qs(data.maintenance), editionText(data)));
    std::vector<std::string> lines;
    for (const AreaReport& a : data.areas)
        if (a.requirement) {
            const std::string line = describeRequirement(*a.requirement, lightingStandardOf(*data.scene));
            if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
        }
    for (const std::string& line : lines) flow.paragraph(qs(line), flow.fonts().small, flow.mm(4));
    if (data.renders) {
        flow.subheading(QStringLiteral("Renders"));
        const QString stop = data.settings.renderRelmse > 0
                                 ? QStringLiteral("until its estimated relative error (relMSE) is at most %1, read every "
                                                  "8 passes from 16 on, or %2 passes at most: %3 passes")
                                       .arg(QString::number(data.settings.renderRelmse, 'g', 3))
                                       .arg(data.settings.renderSpp)
                                       .arg(data.renders->passes)
                                 : QStringLiteral("for %1 passes").arg(data.settings.renderSpp);
        flow.paragraph(QStringLiteral("The camera's view is rendered by %1, which measures each method that is "
                                      "consistent for the scene in short pilots, gives the time where it takes the "
                                      "most off the error and combines the methods' films (%2), %3; its estimated "
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
