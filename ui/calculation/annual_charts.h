#pragma once
// The Annual dock's two pictures: a grid's points in the false colour of one metric, laid out as
// the plan shows them (x across, z down; a click picks a point), and one point's hourly
// illuminance over the year as a heat map (days across, hours down, lux on a log scale), each
// with its legend.

#include "core/daylight/annual_metrics.h"
#include "core/math.h"
#include "render/display/false_colour.h"

#include <QWidget>

#include <vector>

namespace lucerna {

class AnnualGridMap : public QWidget {
    Q_OBJECT
public:
    explicit AnnualGridMap(QWidget* parent = nullptr);

    // One value per point (scene units for `points`; cells of `cellSize` scene units), `excluded`
    // points (inside geometry) hatched grey.
    void setValues(const std::vector<V3d>& points, double cellSize, std::vector<double> values, const Legend& legend,
                   std::vector<uint8_t> excluded);
    void setSelected(int index);
    int selected() const { return selected_; }
    QSize sizeHint() const override { return {320, 220}; }

signals:
    void pointClicked(int index);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent* event) override;

private:
    // The cell's rectangle in the widget (the legend keeps the right edge).
    QRectF cellRect(size_t index) const;

    std::vector<V3d> points_;
    double cellSize_ = 1;
    std::vector<double> values_;
    std::vector<uint8_t> excluded_;
    Legend legend_;
    int selected_ = -1;
};

class YearHeatMap : public QWidget {
    Q_OBJECT
public:
    explicit YearHeatMap(QWidget* parent = nullptr);

    // The rows of the year and one value per row (lux).
    void setYear(const std::vector<AnnualHour>& hours, std::vector<float> lux);
    QSize sizeHint() const override { return {380, 160}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    std::vector<AnnualHour> hours_;
    std::vector<float> lux_;
};

}  // namespace lucerna
