#include "ui/calculation/ugr_grid.h"

#include "core/number_format.h"
#include "render/display/display.h"

#include <QBrush>
#include <QTableWidget>

#include <cmath>
#include <sstream>

namespace lucerna {

V3d gridViewDirection(const CalculationGrid& grid, GridViewDirection direction) {
    switch (direction) {
    case GridViewDirection::PlusU: return grid.edgeU;
    case GridViewDirection::MinusU: return -grid.edgeU;
    case GridViewDirection::PlusV: return grid.edgeV;
    case GridViewDirection::MinusV: return -grid.edgeV;
    }
    return grid.edgeU;
}

std::vector<V3d> observerPositions(const GridLayout& layout, double floorY, double metersPerUnit, double eyeHeightM) {
    std::vector<V3d> eyes;
    eyes.reserve(layout.points.size());
    for (const V3d& p : layout.points) eyes.emplace_back(p.x, floorY + eyeHeightM / metersPerUnit, p.z);
    return eyes;
}

QColor ugrColour(double ugr) { return falseColourRamp(std::clamp((ugr - 10.0) / 20.0, 0.0, 1.0)); }

void fillUgrTable(QTableWidget& table, const GridLayout& layout, const GlareGridResult& result) {
    table.setRowCount(layout.nv);
    table.setColumnCount(layout.nu);
    for (int j = 0; j < layout.nv; ++j)
        for (int i = 0; i < layout.nu; ++i) {
            const size_t k = size_t(j) * size_t(layout.nu) + size_t(i);
            const GlareResult& r = result.observers[k];
            auto* item = new QTableWidgetItem;
            item->setTextAlignment(Qt::AlignCenter);
            if (!r.ugr) {
                item->setText(QStringLiteral("-"));
                item->setForeground(QColor(90, 90, 90));
                item->setToolTip(r.sources.empty() ? QObject::tr("No luminaire in the field of view")
                                                   : QObject::tr("No indirect light reaches the eye: UGR undefined"));
            } else {
                item->setText(QString::number(*r.ugr, 'f', 1));
                const QColor c = ugrColour(*r.ugr);
                item->setBackground(c);
                item->setForeground(c.lightnessF() > 0.55 ? Qt::black : Qt::white);
                QString tip = QObject::tr("UGR %1 +- %2 (95%)\nLb %3 cd/m^2")
                                  .arg(*r.ugr, 0, 'f', 1)
                                  .arg(r.ugrErrorBar, 0, 'f', 1)
                                  .arg(r.backgroundLuminanceCdM2, 0, 'f', 1);
                if (!r.sources.empty())
                    tip += QObject::tr("\nstrongest: %1 (%2%)")
                               .arg(QString::fromStdString(r.sources.front().light))
                               .arg(100 * r.sources.front().share, 0, 'f', 0);
                item->setToolTip(tip);
            }
            table.setItem(layout.nv - 1 - j, i, item);
        }
}

QStringList ugrFigures(const GlareGridResult& result, const GridLayout& layout, double eyeHeightM, const QString& view) {
    double hi = -1e300, lo = 1e300, lbLo = 1e300, lbHi = 0, bar = 0;
    size_t hiAt = 0, loAt = 0;
    int rated = 0;
    for (size_t k = 0; k < result.observers.size(); ++k) {
        const GlareResult& r = result.observers[k];
        if (!r.ugr) continue;
        ++rated;
        if (*r.ugr > hi) hi = *r.ugr, hiAt = k;
        if (*r.ugr < lo) lo = *r.ugr, loAt = k;
        lbLo = std::min(lbLo, r.backgroundLuminanceCdM2);
        lbHi = std::max(lbHi, r.backgroundLuminanceCdM2);
        bar = std::max(bar, r.ugrErrorBar);
    }
    const auto where = [&](size_t k) {
        // As the table numbers them: rows from the far side down.
        return QObject::tr("(column %1, row %2)").arg(int(k) % layout.nu + 1).arg(layout.nv - int(k) / layout.nu);
    };
    QStringList lines;
    lines << QObject::tr("UGR of %1 observers (the new installation), eyes %2 m above the floor, looking %3")
                 .arg(result.observers.size())
                 .arg(eyeHeightM, 0, 'f', 1)
                 .arg(view);
    if (rated == 0) {
        lines << QObject::tr("No luminaire in the field of view of any observer");
        return lines;
    }
    lines << QObject::tr("UGR max %1 %2, min %3 %4").arg(hi, 0, 'f', 1).arg(where(hiAt)).arg(lo, 0, 'f', 1).arg(where(loAt));
    lines << QObject::tr("Lb %1 to %2 cd/m^2; UGR error bar at most %3 (95%), %4")
                 .arg(lbLo, 0, 'f', 1)
                 .arg(lbHi, 0, 'f', 1)
                 .arg(bar, 0, 'f', 2)
                 .arg(QString::fromLatin1(gridMethodName(result.method)));
    if (rated < int(result.observers.size()))
        lines << QObject::tr("%1 observers see no luminaire (shown -)").arg(int(result.observers.size()) - rated);
    return lines;
}

std::string ugrCsv(const GridLayout& layout, const std::vector<V3d>& eyes, const GlareGridResult& result) {
    std::ostringstream s;
    s << "i,j,x,y,z,ugr,error,background_cd_m2\n";
    for (size_t k = 0; k < result.observers.size() && k < eyes.size(); ++k) {
        const GlareResult& r = result.observers[k];
        s << k % size_t(layout.nu) << "," << k / size_t(layout.nu) << "," << shortestNumber(eyes[k].x) << ","
          << shortestNumber(eyes[k].y) << "," << shortestNumber(eyes[k].z) << ",";
        if (r.ugr)
            s << shortestNumber(*r.ugr) << "," << shortestNumber(r.ugrErrorBar) << ","
              << shortestNumber(r.backgroundLuminanceCdM2);
        else s << ",,";
        s << "\n";
    }
    return s.str();
}

}  // namespace lucerna
