#include "ui/calculation/ugr_table.h"

#include "render/display/display.h"

#include <QBrush>
#include <QTableWidget>

#include <algorithm>

namespace lucerna {

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

}  // namespace lucerna
