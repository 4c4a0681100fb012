#include "ui/rendering/error_plot.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace lucerna {

ErrorPlot::ErrorPlot(QWidget* parent) : QWidget(parent) { setMinimumHeight(90); }

void ErrorPlot::setPoints(std::vector<QPointF> points) {
    points_.clear();
    for (const QPointF& p : points)
        if (p.x() > 0 && p.y() > 0 && std::isfinite(p.y())) points_.push_back(p);
    update();
}

void ErrorPlot::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(250, 250, 250));
    const QRectF plot = QRectF(rect()).adjusted(44, 8, -8, -20);
    painter.setPen(QColor(160, 160, 160));
    painter.drawRect(plot);
    painter.setPen(Qt::black);
    painter.drawText(QRectF(plot.left(), plot.bottom() + 2, plot.width(), 16), Qt::AlignCenter,
                     tr("estimated relmse against time (log-log)"));
    if (points_.size() < 2) return;
    double t0 = points_.front().x(), t1 = points_.back().x();
    double e0 = points_.front().y(), e1 = e0;
    for (const QPointF& p : points_) e0 = std::min(e0, p.y()), e1 = std::max(e1, p.y());
    // Whole decades on the error axis, so that the labels read as powers of ten.
    const double lo = std::floor(std::log10(e0)), hi = std::max(std::ceil(std::log10(e1)), lo + 1);
    const double lt0 = std::log10(t0), lt1 = std::max(std::log10(t1), lt0 + 1e-3);
    const auto map = [&](const QPointF& p) {
        return QPointF(plot.left() + (std::log10(p.x()) - lt0) / (lt1 - lt0) * plot.width(),
                       plot.bottom() - (std::log10(p.y()) - lo) / (hi - lo) * plot.height());
    };
    painter.drawText(QRectF(0, plot.top() - 6, 42, 14), Qt::AlignRight, QStringLiteral("1e%1").arg(hi));
    painter.drawText(QRectF(0, plot.bottom() - 8, 42, 14), Qt::AlignRight, QStringLiteral("1e%1").arg(lo));
    QPainterPath path(map(points_.front()));
    for (const QPointF& p : points_) path.lineTo(map(p));
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(20, 90, 200), 1.5));
    painter.drawPath(path);
}

}  // namespace lucerna
