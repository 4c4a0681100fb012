#include "ui/calculation/annual_charts.h"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {

// The legend's strip on the right and a margin for its labels.
constexpr int kLegendWidth = 70;

}  // namespace

AnnualGridMap::AnnualGridMap(QWidget* parent) : QWidget(parent) { setMinimumHeight(140); }

void AnnualGridMap::setValues(const std::vector<V3d>& points, double cellSize, std::vector<double> values,
                              const Legend& legend, std::vector<uint8_t> excluded) {
    points_ = points;
    cellSize_ = cellSize > 0 ? cellSize : 1;
    values_ = std::move(values);
    excluded_ = std::move(excluded);
    legend_ = legend;
    if (selected_ >= int(points_.size())) selected_ = -1;
    update();
}

void AnnualGridMap::setSelected(int index) {
    selected_ = index;
    update();
}

QRectF AnnualGridMap::cellRect(size_t index) const {
    double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300;
    for (const V3d& p : points_) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), z0 = std::min(z0, p.z), z1 = std::max(z1, p.z);
    const double w = x1 - x0 + cellSize_, h = z1 - z0 + cellSize_;
    const QRectF area(8, 8, std::max(1, width() - kLegendWidth - 16), std::max(1, height() - 16));
    const double scale = std::min(area.width() / w, area.height() / h);
    const V3d& p = points_[index];
    return QRectF(area.left() + (p.x - x0) * scale, area.top() + (p.z - z0) * scale, cellSize_ * scale, cellSize_ * scale);
}

void AnnualGridMap::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().window());
    if (points_.empty() || values_.size() != points_.size()) {
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, tr("Compute a year to see its figures per point."));
        return;
    }
    for (size_t i = 0; i < points_.size(); ++i) {
        const QRectF r = cellRect(i);
        if (i < excluded_.size() && excluded_[i]) {
            painter.fillRect(r, QBrush(Qt::gray, Qt::BDiagPattern));
            continue;
        }
        painter.fillRect(r, legendColour(legend_, values_[i]));
    }
    if (selected_ >= 0) {
        painter.setPen(QPen(Qt::black, 2));
        painter.drawRect(cellRect(size_t(selected_)));
    }
    paintLegend(painter, rect(), legend_);
}

void AnnualGridMap::mousePressEvent(QMouseEvent* event) {
    for (size_t i = 0; i < points_.size(); ++i)
        if (cellRect(i).contains(event->position())) {
            setSelected(int(i));
            emit pointClicked(int(i));
            return;
        }
}

YearHeatMap::YearHeatMap(QWidget* parent) : QWidget(parent) { setMinimumHeight(120); }

void YearHeatMap::setYear(const std::vector<AnnualHour>& hours, std::vector<float> lux) {
    hours_ = hours;
    lux_ = std::move(lux);
    update();
}

void YearHeatMap::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), palette().window());
    if (hours_.empty() || lux_.size() != hours_.size()) {
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, tr("Click a point to see its year, hour by hour."));
        return;
    }
    // Days across, hours down (midnight at the top), 10 lx to 100,000 lx on a log scale; night
    // and anything under 10 lx at the ramp's foot.
    const Legend legend{10, 100000, true, tr("lx")};
    const int days = int(hours_.size() / 24);
    const QRectF area(34, 6, std::max(1, width() - kLegendWidth - 40), std::max(1, height() - 24));
    const double cw = area.width() / days, ch = area.height() / 24;
    for (size_t row = 0; row < hours_.size(); ++row) {
        const int day = int(row / 24), hour = hours_[row].hour - 1;
        painter.fillRect(QRectF(area.left() + day * cw, area.top() + hour * ch, cw + 0.5, ch + 0.5),
                         legendColour(legend, std::max(double(lux_[row]), 10.0)));
    }
    painter.setPen(palette().text().color());
    for (int h : {0, 6, 12, 18, 24})
        painter.drawText(QRectF(0, area.top() + h * ch - 7, 30, 14), Qt::AlignRight | Qt::AlignVCenter, QString("%1h").arg(h));
    static const char* kMonths[] = {"J", "F", "M", "A", "M", "J", "J", "A", "S", "O", "N", "D"};
    for (size_t row = 0; row < hours_.size(); row += 24)
        if (hours_[row].day == 1)
            painter.drawText(QRectF(area.left() + (row / 24) * cw, area.bottom() + 2, 20, 14), Qt::AlignLeft,
                             kMonths[hours_[row].month - 1]);
    paintLegend(painter, rect(), legend);
}

}  // namespace lucerna
