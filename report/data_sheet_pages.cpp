#include "report/report_pages.h"
#include "report/report_text.h"

#include "render/display/polar_diagram.h"

#include <QPainter>

#include <cmath>

namespace lucerna {

namespace {

constexpr double kPolarMm = 78;  // the diagram's height; the circle fills it less its labels

QString dashOr(const std::optional<double>& x, int decimals, const QString& unit = QString()) {
    return x ? QString::number(*x, 'f', decimals) + unit : QStringLiteral("-");
}

QString title(const LuminaireDataSheet& s) { return s.product.empty() ? qs(s.file) : qs(s.product); }

std::vector<std::pair<QString, QString>> facts(const LuminaireDataSheet& s) {
    std::vector<std::pair<QString, QString>> f;
    f.emplace_back(QStringLiteral("Luminaire"), s.product.empty() ? QStringLiteral("- (the file names none)") : qs(s.product));
    f.emplace_back(QStringLiteral("Photometric file"), qs(s.file));
    f.emplace_back(QStringLiteral("In this scene"), QStringLiteral("%1 luminaire(s) of %2 lm each as installed (new)")
                                                       .arg(s.count)
                                                       .arg(QString::number(s.lumensEach, 'f', 0)));
    f.emplace_back(QStringLiteral("Luminous flux"), QString::number(s.fileLumens, 'f', 0) +
                                                        QStringLiteral(" lm (the file's intensity table, integrated)"));
    f.emplace_back(QStringLiteral("Power"), dashOr(s.watts, 1, QStringLiteral(" W")));
    f.emplace_back(QStringLiteral("Efficacy"), dashOr(s.efficacy(), 1, QStringLiteral(" lm/W")));
    QString cct = dashOr(s.temperatureK, 0, QStringLiteral(" K"));
    if (s.sceneTemperatureK)
        cct += QStringLiteral(" (the scene renders it at %1 K)").arg(QString::number(*s.sceneTemperatureK, 'f', 0));
    f.emplace_back(QStringLiteral("CCT"), cct);
    f.emplace_back(QStringLiteral("Ra"), dashOr(s.colourRenderingIndex, 0));
    const GoniometricDistribution& d = *s.distribution;
    const double down = d.downwardFraction();
    f.emplace_back(QStringLiteral("Light output"), QStringLiteral("%1% downward, %2% upward")
                                                       .arg(QString::number(100 * down, 'f', 0), QString::number(100 * (1 - down), 'f', 0)));
    f.emplace_back(QStringLiteral("Peak intensity"),
                   QString::number(d.maxIntensity() * s.cdPerKlmPerTableCd(), 'f', 0) + QStringLiteral(" cd/klm"));
    QString area = QStringLiteral("- (none stated: UGR does not rate it)");
    if (!s.luminousArea.empty()) {
        area = QStringLiteral("%1 x %2 m (C90-C270 x C0-C180)")
                   .arg(QString::number(s.luminousArea.widthM, 'f', 3), QString::number(s.luminousArea.lengthM, 'f', 3));
        if (s.luminousArea.elliptical) area += QStringLiteral(", round");
        area += s.luminousAreaFromScene ? QStringLiteral(", the scene's luminous_area") : QStringLiteral(", as the file states");
    }
    f.emplace_back(QStringLiteral("Luminous area"), area);
    return f;
}

void addPolarDiagram(PageFlow& flow, const LuminaireDataSheet& s) {
    PolarDiagramStyle style;
    style.font = flow.fonts().figure;
    style.gridPen = flow.mm(0.15);
    style.curvePen = flow.mm(0.45);
    style.unit = QStringLiteral("cd/klm");
    const auto distribution = s.distribution;
    const double scale = s.cdPerKlmPerTableCd(), height = flow.mm(kPolarMm);
    flow.figure(height, [distribution, scale, style, height](QPainter& p, const QRectF& r) {
        // Wider than high: room for the legend beside the circle.
        const double w = std::min(r.width(), 1.5 * height);
        paintPolarDiagram(p, QRectF(r.center().x() - w / 2, r.top(), w, r.height()), *distribution, scale, style);
    });
    flow.paragraph(QStringLiteral("Luminous intensity in cd/klm (per 1000 lm of the luminaire's flux), gamma 0 (the "
                                  "nadir) down: the C0-C180 plane solid, C0 to the right; the C90-C270 plane dashed, "
                                  "C90 to the right."),
                   flow.fonts().small);
}

// One spacing's table: the rooms down, the reflectance sets across, crosswise then endwise, with
// a band above naming the two halves.
void addUgrTable(PageFlow& flow, const UgrTable& u) {
    std::vector<ReportColumn> columns{{QStringLiteral("Room\nX x Y"), 1.5}};
    for (int v = 0; v < 2; ++v)
        for (const UgrReflectances& set : kUgrReflectanceSets)
            columns.push_back({QStringLiteral("%1\n%2\n%3")
                                   .arg(QString::number(set.ceiling, 'f', 2), QString::number(set.walls, 'f', 2),
                                        QString::number(set.floor, 'f', 2)),
                               1.0, Qt::AlignRight});
    ReportTable t = tableOf(columns);
    t.compact = true;
    t.header.front() = QStringLiteral("\u03c1 ceiling\n\u03c1 walls\n\u03c1 floor\nroom X x Y");
    for (size_t k = 0; k < kUgrRooms.size() && k < u.values.size(); ++k) {
        QStringList row{QStringLiteral("%1H x %2H").arg(kUgrRooms[k].x).arg(kUgrRooms[k].y)};
        for (int v = 0; v < 2; ++v)
            for (double x : u.values[k][size_t(v)]) row << (std::isfinite(x) ? QString::number(x, 'f', 1) : QStringLiteral("-"));
        t.rows.push_back(row);
    }
    const QFont font = flow.fonts().figureBold;
    const double band = flow.lineHeight(font) + flow.mm(1.2);
    const QString heading = QStringLiteral("UGR table, spacing-to-height S = %1H, %2 lm")
                                .arg(QString::number(u.spacingToHeight, 'f', 2), QString::number(u.fluxLm, 'f', 0));
    // The heading, the band (a figure: its height and a 2 mm gap) and the table stay together.
    flow.ensure(std::min(flow.subheadingHeight() + band + flow.mm(3) + flow.tableHeight(t), flow.pageHeight()));
    flow.subheading(heading);
    // The band: "viewed crosswise" over the first five sets, "viewed endwise" over the others
    // (the columns' weights: 1.5 for the rooms, 1 for each set).
    flow.figure(band, [font](QPainter& p, const QRectF& r) {
        const double unit = r.width() / 11.5;
        p.setFont(font);
        p.setPen(Qt::black);
        const QRectF cross(r.left() + 1.5 * unit, r.top(), 5 * unit, r.height());
        const QRectF end(r.left() + 6.5 * unit, r.top(), 5 * unit, r.height());
        p.drawText(cross, Qt::AlignCenter, QStringLiteral("viewed crosswise"));
        p.drawText(end, Qt::AlignCenter, QStringLiteral("viewed endwise"));
        p.setPen(QPen(QColor(150, 150, 150), r.height() / 20));
        for (const QRectF& half : {cross, end}) {
            const double y = r.bottom() - r.height() / 10;
            p.drawLine(QPointF(half.left() + unit / 8, y), QPointF(half.right() - unit / 8, y));
        }
    });
    flow.table(t);
}

void addUgr(PageFlow& flow, const LuminaireDataSheet& s) {
    if (s.ugr.empty()) {
        flow.subheading(QStringLiteral("UGR table"));
        flow.paragraph(QStringLiteral("Not computed: %1.").arg(qs(s.ugrMissing)));
        return;
    }
    for (const UgrTable& u : s.ugr) addUgrTable(flow, u);
    QString command = QStringLiteral("lucerna glare --table %1 --lumens %2").arg(qs(s.file), QString::number(s.lumensEach, 'f', 0));
    if (s.luminousAreaFromScene)
        command += QStringLiteral(" --luminous-area %1,%2")
                       .arg(QString::number(s.luminousArea.widthM, 'g', 6), QString::number(s.luminousArea.lengthM, 'g', 6));
    flow.paragraph(QStringLiteral("UGR by CIE 117's tabular method in CIE 190's layout, for the flux as installed: an "
                                  "observer at the middle of a wall at eye level, the luminaires H above the eye in "
                                  "the centres of square cells of side S; X across, Y along the line of sight; "
                                  "reflectances of ceiling, walls and floor cavity. Crosswise: the line of sight "
                                  "along C0-C180, toward C0; endwise: along C90-C270, toward C90. \"-\": no luminaire "
                                  "in the field of view. Tables for another flux F0 differ by 8 log10(flux / F0). "
                                  "In the scene's folder, %1 prints them.")
                       .arg(command),
                   flow.fonts().small);
}

}  // namespace

void addDataSheetPages(PageFlow& flow, const ReportData& data) {
    for (const LuminaireDataSheet& s : data.dataSheets) {
        flow.newPage();
        flow.heading(QStringLiteral("Luminaire data sheet: %1").arg(title(s)));
        flow.keyValues(facts(s), 0.25);
        addPolarDiagram(flow, s);
        addUgr(flow, s);
    }
}

}  // namespace lucerna
