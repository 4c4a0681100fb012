#pragma once
// The live plot of the estimated error (relmse from the film's half-buffers) against render
// time, both axes logarithmic: a converging render draws a falling line of slope about -1.

#include <QPointF>
#include <QWidget>

#include <vector>

namespace lucerna {

class ErrorPlot : public QWidget {
    Q_OBJECT
public:
    explicit ErrorPlot(QWidget* parent = nullptr);
    // (seconds, estimated relmse), in time order; non-positive values are skipped.
    void setPoints(std::vector<QPointF> points);
    QSize sizeHint() const override { return {300, 110}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    std::vector<QPointF> points_;
};

}  // namespace lucerna
