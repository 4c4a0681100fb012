#include "report/plan_figure.h"
#include "report/report_pages.h"
#include "report/report_text.h"
#include "render/photometry/grid_text.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {

constexpr size_t kMaxListedPoints = 2000;  // beyond: the values are the CSV's (`lucerna grid --csv`)
constexpr int kColumnsPerBlock = 12;       // of the table of values, across A4 portrait

QString metres(double sceneUnits, double metersPerUnit) { return QString::number(sceneUnits * metersPerUnit, 'f', 2); }

QString point(const V3d& p, double mpu) {
    return QStringLiteral("%1, %2, %3").arg(metres(p.x, mpu), metres(p.y, mpu), metres(p.z, mpu));
}

// A direction as a designer names it when it lies along an axis ("+x", "-z"), else its vector.
QString direction(const V3d& d) {
    const V3d n = d.normalized();
    const char* names[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a)
        if (std::abs(n[a]) > 0.999) return QStringLiteral("%1%2").arg(n[a] > 0 ? '+' : '-').arg(names[a]);
    return QString::asprintf("(%.2f, %.2f, %.2f)", n.x, n.y, n.z);
}

// `asked`: the scene's edition; an entry of another (the 2021 table lacks it) says so.
QString requirementsText(const ActivityRequirement& a, StandardEdition asked) {
    QString text = QStringLiteral("Em \u2265 %1 lx, U0 \u2265 %2, UGR \u2264 %3, Ra \u2265 %4")
                       .arg(a.maintainedLux)
                       .arg(QString::number(a.uniformity, 'f', 2))
                       .arg(a.ugrLimit)
                       .arg(a.colourRendering);
    if (a.modifiedLux > 0) text += QStringLiteral(" (Em,u %1 lx where the context asks more: stated, not checked)").arg(a.modifiedLux);
    const auto surface = [&](const char* name, const char* u0, double lux, double uniformity) {
        if (lux > 0) text += QStringLiteral(", %1 \u2265 %2 lx").arg(QLatin1String(name)).arg(lux);
        if (uniformity > 0) text += QStringLiteral(", %1 \u2265 %2").arg(QLatin1String(u0), QString::number(uniformity, 'f', 2));
    };
    surface("Ez", "U0,z", a.cylindricalLux, a.cylindricalUniformity);
    surface("Ewall", "U0,wall", a.wallLux, a.wallUniformity);
    surface("Eceiling", "U0,ceiling", a.ceilingLux, a.ceilingUniformity);
    text += QStringLiteral(" (%1").arg(QLatin1String(standardEditionName(a.edition)));
    if (a.edition != asked)
        text += QStringLiteral("; %1 asked, whose table here lacks this activity").arg(QLatin1String(standardEditionName(asked)));
    return text + QStringLiteral(")");
}

QString gridText(const AreaReport& a, double mpu) {
    const double w = a.grid.edgeU.length() * mpu, l = a.grid.edgeV.length() * mpu;
    QString text = QStringLiteral("%1 m x %2 m, %3 x %4 points, spacing %5 x %6 m")
                       .arg(QString::number(w, 'f', 2), QString::number(l, 'f', 2))
                       .arg(a.layout.nu)
                       .arg(a.layout.nv)
                       .arg(QString::number(a.layout.spacingUMeters, 'g', 3), QString::number(a.layout.spacingVMeters, 'g', 3));
    const V3d n = a.grid.normal();
    if (n.y > 0.9) text += QStringLiteral(", at height %1 m, facing up").arg(metres(a.grid.corner.y, mpu));
    else if (n.y < -0.9)  // u x v points down: a ceiling's grid, or edges given in the wrong order
        text += QStringLiteral(", at height %1 m, facing down (the light from below)").arg(metres(a.grid.corner.y, mpu));
    else text += QStringLiteral(", facing %1").arg(direction(n));
    return text;
}

// A check's quantity as the table names it.
QString quantityText(const std::string& q) {
    if (q == "Em") return QStringLiteral("Em (maintained, Eavg)");
    if (q == "U0") return QStringLiteral("U0 = Emin / Eavg");
    if (q == "UGR") return QStringLiteral("UGR (worst observer)");
    if (q == "Ra") return QStringLiteral("Ra (lowest luminaire)");
    if (q == "Ez") return QStringLiteral("Ez (cylindrical, mean)");
    if (q == "U0,z") return QStringLiteral("U0,z of Ez");
    if (q == "Ewall") return QStringLiteral("Ewall (walls, mean)");
    if (q == "U0,wall") return QStringLiteral("U0,wall");
    if (q == "Eceiling") return QStringLiteral("Eceiling (ceiling, mean)");
    if (q == "U0,ceiling") return QStringLiteral("U0,ceiling");
    return qs(q);
}

void addCheckRow(ReportTable& t, const RequirementCheck& c, const QString& prefix) {
    const bool lx = !c.quantity.empty() && c.quantity[0] == 'E';
    const bool u0 = c.quantity.rfind("U0", 0) == 0;
    const int decimals = c.quantity == "U0" ? 3 : u0 ? 2 : c.quantity == "UGR" ? 1 : 0;
    const auto figure = [&](double x) { return lx ? lux(x) + QStringLiteral(" lx") : QString::number(x, 'f', decimals); };
    const QString required = QString(c.upperLimit ? QStringLiteral("\u2264 ") : QStringLiteral("\u2265 ")) +
                             (lx ? QString::number(c.required, 'f', 0) + QStringLiteral(" lx")
                                 : QString::number(c.required, 'f', u0 ? 2 : 0));
    QString margin = QStringLiteral("-");
    if (c.achieved) {
        margin = (c.margin >= 0 ? QStringLiteral("+") : QString()) + figure(c.margin);
        if (lx && c.required > 0) margin += QString::asprintf(" (%+.1f%%)", 100 * c.margin / c.required);
    }
    QString achieved = c.achieved ? figure(*c.achieved) : QStringLiteral("-");
    if (c.achieved && c.error > 0) achieved += QStringLiteral(" \u00b1 ") + figure(c.error);
    // "not checked: no maintenance factor" without its parenthesis, which the note under the
    // table gives once for every lux figure.
    QString outcome = outcomeText(c);
    if (const qsizetype cut = outcome.indexOf(QStringLiteral(" (")); c.outcome == CheckOutcome::NotChecked && cut > 0)
        outcome.truncate(cut);
    t.rows.push_back({prefix + quantityText(c.quantity), achieved, required, margin, outcome});
}

// Achieved, required, margin, outcome of each check: the area's, then its zones'.
ReportTable checksTable(const AreaReport& a) {
    ReportTable t;
    t.header = {QStringLiteral("Quantity"), QStringLiteral("Calculated"), QStringLiteral("Required"),
                QStringLiteral("Margin"), QStringLiteral("Outcome")};
    t.weights = {1.9, 1.2, 0.8, 1.3, 1.4};
    t.alignment = {Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight, Qt::AlignLeft};
    for (const RequirementCheck& c : a.checks) addCheckRow(t, c, QString());
    for (const ZoneReport& z : a.zones) {
        QString name = qs(z.name) + QStringLiteral(": ");
        name[0] = name[0].toUpper();
        for (const RequirementCheck& c : z.checks) addCheckRow(t, c, name);
    }
    return t;
}

void addGlare(PageFlow& flow, const ReportData& data, const AreaReport& a) {
    if (!data.settings.glare || a.glare.empty()) {
        flow.subheading(QStringLiteral("Glare: unified glare rating (UGR)"));
        flow.paragraph(data.schedule.luminaires == 0
                           ? QStringLiteral("No electric lighting is switched on: UGR, which rates electric lighting "
                                            "(CIE 117), does not apply.")
                           : QStringLiteral("Not computed for this report."));
        return;
    }
    const double mpu = data.scene->metersPerUnit;
    ReportTable t;
    t.header = {QStringLiteral("Observer"), QStringLiteral("Eye at x, y, z [m]"), QStringLiteral("Looking"),
                QStringLiteral("UGR"), QStringLiteral("\u00b1 (95%)"), QStringLiteral("Lb [cd/m\u00b2]")};
    t.weights = {0.9, 1.9, 1.2, 0.7, 0.8, 0.9};
    t.alignment = {Qt::AlignLeft, Qt::AlignLeft, Qt::AlignLeft, Qt::AlignRight, Qt::AlignRight, Qt::AlignRight};
    std::vector<QString> notes;
    for (size_t i = 0; i < a.glare.size(); ++i) {
        const ObserverGlare& o = a.glare[i];
        const bool has = o.result.ugr.has_value();
        t.rows.push_back({QString::number(i + 1), point(o.observer.position, mpu), direction(o.observer.view),
                          has ? QString::number(*o.result.ugr, 'f', 1) : QStringLiteral("-"),
                          has ? QString::number(o.result.ugrErrorBar, 'f', 1) : QStringLiteral("-"),
                          has ? QString::number(o.result.backgroundLuminanceCdM2, 'f', 1) : QStringLiteral("-")});
    }
    // What was left out, once for all observers when all say it.
    for (size_t i = 0; i < a.glare.size(); ++i)
        for (const std::string& n : a.glare[i].result.notes) {
            const bool everyone = std::all_of(a.glare.begin(), a.glare.end(), [&](const ObserverGlare& o) {
                return std::find(o.result.notes.begin(), o.result.notes.end(), n) != o.result.notes.end();
            });
            const QString line = everyone ? QStringLiteral("All observers: %1").arg(qs(n))
                                          : QStringLiteral("Observer %1: %2").arg(i + 1).arg(qs(n));
            if (std::find(notes.begin(), notes.end(), line) == notes.end()) notes.push_back(line);
        }
    flow.ensure(std::min(flow.subheadingHeight() + flow.tableHeight(t), flow.pageHeight()));
    flow.subheading(QStringLiteral("Glare: unified glare rating (UGR)"));
    if (!t.rows.empty()) flow.table(t);
    QString about;
    if (!a.glare.empty() && a.glare.front().defaultObserver)
        about = QStringLiteral("The area names no observers: four seated observers (eyes %1 m above the floor) at the "
                               "middle of its edges, each looking across it. ")
                    .arg(QString::number(data.settings.eyeHeightM, 'f', 2));
    about += QStringLiteral("UGR of the new installation (CIE 117); Lb: the background luminance. The plan shows "
                            "each observer by its number, with an arrow along its line of sight.");
    flow.paragraph(about, flow.fonts().small);
    for (const QString& n : notes) flow.paragraph(n, flow.fonts().small);
}

// The values as a matrix that reads like the plan (the plan's top row first), in blocks of
// columns that fit the page's width; rows split between pages with the header repeated.
void addValues(PageFlow& flow, const ReportData& data, const AreaReport& a) {
    const GridLayout& l = a.layout;
    if (l.points.size() > kMaxListedPoints || a.result.lux.size() != l.points.size()) {
        flow.subheading(QStringLiteral("Illuminance at the grid points [lx]"));
        flow.paragraph(QStringLiteral("%1 points: too many to list here; `lucerna grid` with this area's corner, "
                                      "edges and spacing and --csv writes them.")
                           .arg(l.points.size()));
        return;
    }
    const double mpu = data.scene->metersPerUnit;
    const V3d u = a.grid.edgeU.normalized(), v = a.grid.edgeV.normalized();
    const bool plan = std::abs(a.grid.normal().y) > 0.9;
    // A horizontal grid whose edges run along x and z (in either order) reads like the plan:
    // x to the right, z down, labelled with world coordinates. Others: u across, v up (a wall)
    // or down, labelled with the distance along the edges from the corner.
    const bool uAlongX = std::abs(u.x) > 0.999 && std::abs(v.z) > 0.999;
    const bool uAlongZ = std::abs(u.z) > 0.999 && std::abs(v.x) > 0.999;
    const bool world = plan && (uAlongX || uAlongZ);
    const bool acrossU = !world || uAlongX;  // the table's columns step along u
    const int across = acrossU ? l.nu : l.nv, down = acrossU ? l.nv : l.nu;
    const V3d acrossEdge = acrossU ? u : v, downEdge = acrossU ? v : u;
    const bool acrossForward = !world || acrossEdge.x > 0;
    const bool downForward = world ? downEdge.z > 0 : plan;  // a wall's v goes up: its last row first
    const auto pointAt = [&](int c, int r) {  // c, r: grid indices along the across and down edges
        const int i = acrossU ? c : r, j = acrossU ? r : c;
        return size_t(j) * size_t(l.nu) + size_t(i);
    };
    const double acrossSpacing = acrossU ? l.spacingUMeters : l.spacingVMeters;
    const double downSpacing = acrossU ? l.spacingVMeters : l.spacingUMeters;
    const auto columnLabel = [&](int c) {
        if (world) return QStringLiteral("x %1").arg(metres(l.points[pointAt(c, 0)].x, mpu));
        return QStringLiteral("%1 %2").arg(acrossU ? "u" : "v").arg(QString::number((c + 0.5) * acrossSpacing, 'f', 2));
    };
    const auto rowLabel = [&](int r) {
        if (world) return QStringLiteral("z %1").arg(metres(l.points[pointAt(0, r)].z, mpu));
        return QStringLiteral("%1 %2").arg(acrossU ? "v" : "u").arg(QString::number((r + 0.5) * downSpacing, 'f', 2));
    };
    std::vector<int> columns, rows;
    for (int c = 0; c < across; ++c) columns.push_back(acrossForward ? c : across - 1 - c);
    for (int r = 0; r < down; ++r) rows.push_back(downForward ? r : down - 1 - r);
    bool anyInside = false;
    const int blocks = (across + kColumnsPerBlock - 1) / kColumnsPerBlock;
    std::vector<ReportTable> tables;
    for (int b = 0; b < blocks; ++b) {
        const int c0 = b * kColumnsPerBlock, c1 = std::min(across, c0 + kColumnsPerBlock);
        ReportTable t;
        t.compact = true;
        t.header << QStringLiteral("[m]");
        t.weights.push_back(1.25);
        t.alignment.push_back(Qt::AlignLeft);
        for (int c = c0; c < c1; ++c) {
            t.header << columnLabel(columns[size_t(c)]);
            t.weights.push_back(1.0);
            t.alignment.push_back(Qt::AlignRight);
        }
        for (int c = c1; c < c0 + kColumnsPerBlock && blocks > 1; ++c) t.weights.push_back(1.0);  // same widths
        for (int r : rows) {
            QStringList row{rowLabel(r)};
            for (int c = c0; c < c1; ++c) {
                const size_t k = pointAt(columns[size_t(c)], r);
                anyInside = anyInside || (k < a.result.insideGeometry.size() && a.result.insideGeometry[k]);
                row << qs(gridPointText(a.result, k));
            }
            t.rows.push_back(row);
        }
        if (blocks > 1)
            while (t.header.size() < kColumnsPerBlock + 1) t.header << QString(), t.alignment.push_back(Qt::AlignRight);
        for (QStringList& r : t.rows)
            while (r.size() < t.header.size()) r << QString();
        tables.push_back(std::move(t));
    }
    // A page the values continue onto says whose they are, above the header row repeated.
    const QString title = QStringLiteral("%1: illuminance at the grid points [lx]").arg(qs(a.name));
    for (int b = 0; b < blocks; ++b) {
        const int c0 = b * kColumnsPerBlock, c1 = std::min(across, c0 + kColumnsPerBlock);
        const QString columnsText = QStringLiteral("columns %1 to %2 of %3").arg(c0 + 1).arg(c1).arg(across);
        tables[size_t(b)].continuedTitle =
            (blocks > 1 ? QStringLiteral("%1, %2").arg(title, columnsText) : title) + QStringLiteral(" (continued)");
    }
    // The heading stays with the table (the first block, and its "Columns" line).
    const double columnsLine = blocks > 1 ? flow.lineHeight(flow.fonts().small) : 0;
    flow.ensure(std::min(flow.subheadingHeight() + columnsLine + flow.tableHeight(tables.front()), flow.pageHeight()));
    flow.subheading(QStringLiteral("Illuminance at the grid points [lx]"));
    for (int b = 0; b < blocks; ++b) {
        if (blocks > 1) {
            const int c0 = b * kColumnsPerBlock, c1 = std::min(across, c0 + kColumnsPerBlock);
            const double needed = std::min(columnsLine + flow.tableHeight(tables[size_t(b)]), flow.pageHeight());
            if (b > 0 && flow.y() > flow.top() && flow.remaining() < needed) {
                // A later block on a page of its own: the title, as for a split table.
                flow.newPage();
                flow.paragraph(QStringLiteral("%1 (continued)").arg(title), flow.fonts().bodyBold);
            } else if (b > 0) {
                flow.ensure(needed);
            }  // the first block: under its heading, which kept room for it
            flow.paragraph(QStringLiteral("Columns %1 to %2 of %3").arg(c0 + 1).arg(c1).arg(across), flow.fonts().small);
        }
        flow.table(tables[size_t(b)]);
    }
    QString note = world  ? QStringLiteral("Rows and columns as the plan shows them (seen from above).")
                   : plan ? QStringLiteral("Columns along u, rows along v, from the area's corner.")
                          : QStringLiteral("Rows from the top of the area (v up), columns along u.");
    if (anyInside) note += QStringLiteral(" \"inside\": a point inside geometry, left out of Eavg, Emin, Emax and U0.");
    flow.paragraph(note, flow.fonts().small);
}

}  // namespace

void addAreaPages(PageFlow& flow, const ReportData& data, const AreaReport& a) {
    flow.newPage();
    const Scene& scene = *data.scene;
    const double mpu = scene.metersPerUnit;
    flow.heading(QStringLiteral("Task area: %1").arg(qs(a.name)));
    std::vector<std::pair<QString, QString>> facts;
    facts.emplace_back(QStringLiteral("Activity"), a.requirement ? activityText(*a.requirement)
                                                                 : QStringLiteral("none given: no requirements checked"));
    if (a.requirement) facts.emplace_back(QStringLiteral("Requirements"), requirementsText(*a.requirement, lightingStandardOf(scene)));
    facts.emplace_back(QStringLiteral("Grid"), gridText(a, mpu));
    if (a.defaultWorkPlane)
        facts.emplace_back(QStringLiteral("Area"), QStringLiteral("the scene names no task areas: the work plane 0.8 m "
                                                                  "above the floor, less a 0.5 m band along the walls"));
    facts.emplace_back(QStringLiteral("Values"), qs(data.maintenance));
    flow.keyValues(facts, 0.22);

    PlanValues plan;
    plan.values = a.result.lux;
    plan.insideGeometry = a.result.insideGeometry;
    plan.statistics = a.statistics;
    if (a.requirement) plan.requiredLux = a.requirement->maintainedLux;  // the colours centre on Em
    for (const ObserverGlare& o : a.glare) plan.observers.push_back(o.observer);
    addPlan(flow, data, a, std::move(plan), flow.mm(125));

    flow.subheading(QStringLiteral("Results"));
    flow.paragraph(qs(gridFiguresLine(a.statistics)), flow.fonts().tableBold);
    for (const std::string& line : gridErrorLines(a.result, a.statistics.counted)) flow.paragraph(qs(line), flow.fonts().small);
    if (a.statistics.excluded > 0)
        flow.paragraph(qs(excludedPointsLine(a.statistics, a.layout.points.size())), flow.fonts().small);
    if (data.schedule.wattsPerM2 && a.statistics.average > 0)
        flow.paragraph(QStringLiteral("Specific connected load %1 W/m\u00b2, %2 W/m\u00b2 per 100 lx of this area's Eavg")
                           .arg(QString::number(*data.schedule.wattsPerM2, 'f', 2),
                                QString::number(*data.schedule.wattsPerM2 * 100 / a.statistics.average, 'f', 2)),
                       flow.fonts().small);
    addAreaExtras(flow, data, a);
    const ReportTable checks = checksTable(a);
    if (!checks.rows.empty()) {
        flow.ensure(std::min(flow.subheadingHeight() + flow.tableHeight(checks), flow.pageHeight()));
        flow.subheading(QStringLiteral("Checks against %1").arg(a.requirement ? QLatin1String(standardEditionName(a.requirement->edition))
                                                                               : QLatin1String("EN 12464-1")));
        flow.table(checks);
        const auto unmaintained = [](const RequirementCheck& c) {
            return c.outcome == CheckOutcome::NotChecked && c.notCheckedBecause.rfind("no maintenance factor", 0) == 0;
        };
        bool any = std::any_of(a.checks.begin(), a.checks.end(), unmaintained);
        for (const ZoneReport& z : a.zones) any = any || std::any_of(z.checks.begin(), z.checks.end(), unmaintained);
        if (any)
            flow.paragraph(QStringLiteral("Not checked, no maintenance factor: EN 12464-1's lux requirements are "
                                          "maintained values, and these are the values of the new installation."),
                           flow.fonts().small);
    }
    addGlare(flow, data, a);
    addValues(flow, data, a);
    if (a.daylightFactor) addDaylightFactor(flow, data, a);
    if (a.annual) addAnnualDaylight(flow, data, a);
}

void addPlan(PageFlow& flow, const ReportData& data, const AreaReport& a, PlanValues values, double maxHeight) {
    for (const ZoneReport& z : a.zones) {
        QString label = QStringLiteral("%1 (%2 m)").arg(qs(z.name), QString::number(z.widthMeters, 'g', 3));
        label[0] = label[0].toUpper();
        values.zones.push_back({label, z.grid.strips, z.name == "background area"});
    }
    const double aspect = planAspect(*data.scene, a.grid, values.zones);
    const double height = std::min(flow.width() * aspect + flow.mm(kPlanLegendMm), maxHeight);
    const QFont font = flow.fonts().figure;
    const double dpmm = flow.mm(1);
    flow.figure(height, [&data, &a, values = std::move(values), font, dpmm](QPainter& p, const QRectF& r) {
        paintPlanFigure(p, r, *data.scene, a.grid, a.layout, values, font, dpmm);
    });
}

}  // namespace lucerna
