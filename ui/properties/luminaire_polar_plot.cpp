#include "ui/properties/luminaire_polar_plot.h"

#include "core/photometry/goniometric_distribution.h"
#include "render/display/polar_diagram.h"
#include "ui/properties/property_rows.h"

#include <QLabel>
#include <QPainter>
#include <QVBoxLayout>

#include <algorithm>

namespace lucerna {

// The drawing surface: square, as wide as the panel allows (a narrow dock scales it down rather
// than scrolling sideways to it).
class PolarCanvas : public QWidget {
public:
    static constexpr int kSmallest = 150, kLargest = 320;
    PolarCanvas(LuminairePolarPlot* plot, QWidget* parent) : QWidget(parent), plot_(plot) {
        setMinimumSize(kSmallest, kSmallest);
        QSizePolicy p(QSizePolicy::Ignored, QSizePolicy::Preferred);
        p.setHeightForWidth(true);
        setSizePolicy(p);
    }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int w) const override { return std::clamp(w, kSmallest, kLargest); }
    QSize sizeHint() const override { return {280, 280}; }

protected:
    void paintEvent(QPaintEvent*) override { plot_->paintPlot(this); }

private:
    LuminairePolarPlot* plot_;
};

LuminairePolarPlot::LuminairePolarPlot(QWidget* parent) : QWidget(parent) {
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    canvas_ = new PolarCanvas(this, this);
    canvas_->setObjectName("luminairePolarCanvas");
    peak_ = makeWrappingLabel(this, "luminairePeak");
    v->addWidget(canvas_);
    v->addWidget(peak_);
}

void LuminairePolarPlot::setDistribution(std::shared_ptr<const GoniometricDistribution> distribution,
                                         double cdPerTableCd, double fluxLm) {
    distribution_ = std::move(distribution);
    scale_ = cdPerTableCd;
    peakCd_ = distribution_ ? distribution_->maxIntensity() * scale_ : 0;
    if (!distribution_) peak_->setText(tr("No distribution loaded."));
    else if (fluxLm > 0)
        peak_->setText(tr("Peak %1 cd (%2 cd/klm)").arg(peakCd_, 0, 'f', 0).arg(peakCd_ * 1000 / fluxLm, 0, 'f', 0));
    else peak_->setText(tr("Peak %1 cd").arg(peakCd_, 0, 'f', 0));
    canvas_->update();
}

void LuminairePolarPlot::paintPlot(QWidget* on) const {
    QPainter p(on);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(on->rect(), palette().base());
    if (!distribution_) return;
    PolarDiagramStyle style;
    style.font = on->font();
    style.background = Qt::transparent;
    style.grid = palette().color(QPalette::Mid);
    style.text = palette().color(QPalette::Text);
    paintPolarDiagram(p, QRectF(on->rect()), *distribution_, scale_, style);
}

}  // namespace lucerna
