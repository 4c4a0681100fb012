#pragma once
// A luminaire's light distribution as catalogues draw it (render/display/polar_diagram.h, the
// report's data sheets draw the same): the C0-C180 and C90-C270 planes as two curves in polar
// coordinates, gamma 0 (the nadir) at the bottom, in candela as the scene uses the luminaire (its
// lumens, tilt and the file's table), with rings labelled in cd; under it the peak intensity in
// cd and in cd/klm (per 1000 lm of the luminaire's flux).

#include <QWidget>

#include <memory>

class QLabel;

namespace lucerna {

struct GoniometricDistribution;

class LuminairePolarPlot : public QWidget {
    Q_OBJECT
public:
    explicit LuminairePolarPlot(QWidget* parent = nullptr);

    // cdPerTableCd: the factor from the file's candela to the scene's (lumens / the table's flux,
    // the tilt multiplier); fluxLm: the luminaire's flux as the scene uses it. Null: nothing drawn.
    void setDistribution(std::shared_ptr<const GoniometricDistribution> distribution, double cdPerTableCd,
                         double fluxLm);

    // The largest intensity drawn (cd).
    double peakCandela() const { return peakCd_; }
    QWidget* canvas() const { return canvas_; }
    QLabel* peakLabel() const { return peak_; }

private:
    friend class PolarCanvas;
    void paintPlot(QWidget* on) const;

    std::shared_ptr<const GoniometricDistribution> distribution_;
    double scale_ = 1, peakCd_ = 0;
    QWidget* canvas_;
    QLabel* peak_;
};

}  // namespace lucerna
