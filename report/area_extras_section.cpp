// The area page's EN 12464-1:2021 figures (area_extras.h): Ez over the area, the walls and
// ceiling of its room, the zones around it, each with its error bars, and the modelling ratio
// as guidance. Their checks join the area's one list of checks (area_pages.cpp).

#include "report/report_pages.h"
#include "report/report_text.h"

namespace lucerna {

namespace {

QString withError(double value, const std::optional<GridErrorBars>& errors, double GridErrorBars::*bar, int decimals) {
    QString text = QString::number(value, 'f', decimals);
    if (errors) text += QStringLiteral(" \u00b1 ") + QString::number((*errors).*bar, 'f', decimals);
    return text;
}

QStringList figureRow(const QString& figure, const QString& where, const SurfaceIlluminance& s, int leftOut) {
    if (s.grid.counted == 0)
        return {figure, where, QStringLiteral("-"), QStringLiteral("-"), QStringLiteral("-"), QStringLiteral("0")};
    QString points = QString::number(s.grid.counted);
    if (leftOut > 0) points += QStringLiteral(" (%1)").arg(leftOut);
    return {figure, where, withError(s.grid.average, s.errors, &GridErrorBars::average, 1),
            withError(s.grid.minimum, s.errors, &GridErrorBars::minimum, 1),
            withError(s.grid.uniformity, s.errors, &GridErrorBars::uniformity, 2), points};
}

SurfaceIlluminance zoneIlluminance(const ZoneReport& z) {
    SurfaceIlluminance s{z.statistics, std::nullopt};
    if (!z.result.errorBarUnknown && z.statistics.counted > 0)
        s.errors = gridErrorBars(z.statistics, z.result.lux, z.result.errorLux, z.result.insideGeometry);
    return s;
}

QString metres(double m) { return QString::number(m, 'f', 2) + QStringLiteral(" m"); }

}  // namespace

void addAreaExtras(PageFlow& flow, const ReportData& data, const AreaReport& a) {
    const RoomSurfacesReport* room =
        a.roomSurfaces && *a.roomSurfaces < data.roomSurfaces.size() ? &data.roomSurfaces[*a.roomSurfaces] : nullptr;
    if (!a.cylindrical && !room && a.zones.empty()) return;
    ReportTable t = tableOf({{QStringLiteral("Figure"), 1.15},
                             {QStringLiteral("Where"), 2.1},
                             {QStringLiteral("Eavg [lx]"), 1.15, Qt::AlignRight},
                             {QStringLiteral("Emin [lx]"), 1.15, Qt::AlignRight},
                             {QStringLiteral("U0"), 0.95, Qt::AlignRight},
                             {QStringLiteral("Points (left out)"), 0.9, Qt::AlignRight}});
    const QString roomName = qs(a.room.description);
    if (a.cylindrical) {
        const CylindricalFigures& c = *a.cylindrical;
        const bool standing = c.heightAboveFloorM == kStandingCylindricalHeightM;
        t.rows.push_back(figureRow(QStringLiteral("Ez (cylindrical)"),
                                   QStringLiteral("over the area at %1 above the floor (%2)")
                                       .arg(metres(c.heightAboveFloorM),
                                            standing ? QStringLiteral("standing") : QStringLiteral("seated")),
                                   c.figures, c.figures.grid.excluded));
    }
    if (room) {
        const RoomSurfaceResult& r = room->result;
        t.rows.push_back(figureRow(QStringLiteral("Walls"), QStringLiteral("the four walls of the room"),
                                   surfaceIlluminance(r.walls), r.walls.leftOut));
        if (r.complete)
            t.rows.push_back(figureRow(QStringLiteral("Ceiling"), QStringLiteral("the room's ceiling"),
                                       surfaceIlluminance(r.ceiling), r.ceiling.leftOut));
    }
    for (const ZoneReport& z : a.zones) {
        QString name = qs(z.name);
        name[0] = name[0].toUpper();
        const QString where = z.grid.points.empty()
                                  ? QStringLiteral("a %1 m band: the room leaves none of it").arg(z.widthMeters)
                                  : QStringLiteral("a %1 m band around the %2, spacing %3")
                                        .arg(z.widthMeters)
                                        .arg(z.name == "background area" ? QStringLiteral("zone") : QStringLiteral("area"))
                                        .arg(metres(z.grid.spacingMeters));
        t.rows.push_back(figureRow(name, where, zoneIlluminance(z), z.statistics.excluded));
    }
    flow.ensure(std::min(flow.subheadingHeight() + flow.tableHeight(t), flow.pageHeight()));
    flow.subheading(QStringLiteral("Cylindrical illuminance, walls, ceiling and zones"));
    flow.table(t);
    QStringList notes;
    if (a.cylindrical || room)
        notes << QStringLiteral("The room: %1 (the box of its walls, floor and ceiling; the method page says how it is "
                                "found).")
                     .arg(roomName);
    if (a.modellingRatio)
        notes << QStringLiteral("Modelling (EN 12464-1:2021, 5.2.6; guidance, not a requirement, so not among the "
                                "checks; Eh is the area's Eavg): %1.")
                     .arg(qs(describeModelling(*a.modellingRatio)));
    if (room) {
        QString shared = room->areas.size() > 1
                             ? QStringLiteral(" They are the room's, computed once for its task areas (%1).")
                                   .arg(qs([&] {
                                       std::string s;
                                       for (const std::string& n : room->areas) s += (s.empty() ? "" : ", ") + n;
                                       return s;
                                   }()))
                             : QString();
        notes << QStringLiteral("Walls and ceiling: grids on the faces of the room's box, each point on the surface "
                                "found there; points on glass (dielectric) left out, Eavg weighted by the points' areas; "
                                "error target %1% of each point's value.%2")
                     .arg(QString::number(100 * room->settings.targetRelativeError, 'g', 3), shared);
    }
    notes << QStringLiteral("\u00b1: the 95% error bar; left out: points inside geometry%1.")
                 .arg(room ? QStringLiteral(" or on glass") : QString());
    for (const QString& n : notes) flow.paragraph(n, flow.fonts().small);
}

}  // namespace lucerna
