#include "ui/properties/luminaire_polar_plot.h"

#include "core/photometry/goniometric_distribution.h"
#include "ui/properties/property_rows.h"

#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

// The drawing surface: square, as wide as the panel allows.
class PolarCanvas : public QWidget {
public:
    PolarCanvas(LuminairePolarPlot* plot, QWidget* parent) : QWidget(parent), plot_(plot) {
        setMinimumSize(240, 240);
        QSizePolicy p(QSizePolicy::Preferred, QSizePolicy::Preferred);
        p.setHeightForWidth(true);
        setSizePolicy(p);
    }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int w) const override { return std::clamp(w, 240, 320); }
    QSize sizeHint() const override { return {280, 280}; }

protected:
    void paintEvent(QPaintEvent*) override { plot_->paintPlot(this); }

private:
    LuminairePolarPlot* plot_;
};

double polarRingStep(double peak) {
    if (!(peak > 0)) return 1;
    const double decade = std::pow(10.0, std::floor(std::log10(peak)));
    for (double m : {0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0})
        if (peak / (m * decade) <= 5) return m * decade;
    return 10 * decade;
}

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
    ringStep_ = polarRingStep(peakCd_);
    outerCd_ = std::max(1.0, std::ceil(peakCd_ / ringStep_ - 1e-9)) * ringStep_;
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
    if (!distribution_ || !(peakCd_ > 0)) return;
    const QFontMetrics fm = p.fontMetrics();
    const double margin = fm.height() + 4;
    const double radius = std::min(on->width(), on->height()) / 2.0 - margin;
    if (radius < 10) return;
    const QPointF centre(on->width() / 2.0, on->height() / 2.0);
    constexpr double toRad = std::numbers::pi / 180.0;
    // A direction at gamma on one side of the plane (+1 right: C0 or C90; -1 left: C180 or C270);
    // gamma 0 points down the screen.
    const auto at = [&](double gammaDeg, double side, double r) {
        return centre + QPointF(side * r * std::sin(gammaDeg * toRad), r * std::cos(gammaDeg * toRad));
    };

    // Grid: rings at the step, spokes every 30 degrees, their values.
    const QColor grid = palette().color(QPalette::Mid);
    p.setPen(QPen(grid, 1));
    for (double g = 0; g <= 180; g += 30)
        for (double side : {-1.0, 1.0}) p.drawLine(centre, at(g, side, radius));
    const QColor text = palette().color(QPalette::Text);
    for (double ring = ringStep_; ring <= outerCd_ + 1e-9 * outerCd_; ring += ringStep_) {
        const double r = radius * ring / outerCd_;
        p.setPen(QPen(grid, 1));
        p.drawEllipse(centre, r, r);
        p.setPen(text);
        p.drawText(at(180, 1, r) + QPointF(3, fm.ascent()), QString::number(ring, 'g', 4));
    }
    p.setPen(text);
    const QString bottom = QStringLiteral("0°"), top = QStringLiteral("180°");
    p.drawText(at(0, 1, radius) + QPointF(-fm.horizontalAdvance(bottom) / 2.0, fm.ascent() + 2), bottom);
    p.drawText(at(180, 1, radius) + QPointF(-fm.horizontalAdvance(top) / 2.0, -4), top);
    p.drawText(at(90, -1, radius) + QPointF(2, -4), QStringLiteral("90°"));
    p.drawText(QPointF(on->width() - fm.horizontalAdvance(QStringLiteral("cd")) - 4, fm.ascent() + 2), QStringLiteral("cd"));

    // The two planes: C0 to the right of the nadir and C180 to its left (C90 and C270 likewise).
    struct Plane {
        double right, left;
        QColor colour;
        Qt::PenStyle style;
        QString name;
    };
    const Plane planes[] = {{0, 180, QColor(0, 90, 200), Qt::SolidLine, QStringLiteral("C0-C180")},
                            {90, 270, QColor(200, 40, 40), Qt::DashLine, QStringLiteral("C90-C270")}};
    int legendY = int(fm.ascent()) + 2;
    for (const Plane& plane : planes) {
        QPainterPath path;
        // Around the circle: the right half from the nadir up, then the left half back down.
        for (int i = 0; i <= 360; ++i) {
            const bool right = i <= 180;
            const double g = right ? i : 360 - i;
            const double cd = distribution_->intensity(right ? plane.right : plane.left, g) * scale_;
            const QPointF q = at(g, right ? 1 : -1, radius * cd / outerCd_);
            if (i == 0) path.moveTo(q);
            else path.lineTo(q);
        }
        p.setPen(QPen(plane.colour, 2, plane.style));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
        p.drawLine(QPointF(4, legendY - fm.ascent() / 2.0), QPointF(22, legendY - fm.ascent() / 2.0));
        p.setPen(text);
        p.drawText(QPointF(26, legendY), plane.name);
        legendY += fm.height();
    }
}

}  // namespace lucerna
