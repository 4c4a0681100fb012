#include "ui/compare/compare_canvas.h"

#include "ui/compare/view_transform.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {
constexpr int kGrab = 6;  // px either side of the divider that grab it rather than pan

void caption(QPainter& p, const QRect& area, const QString& text, Qt::Alignment align) {
    if (text.isEmpty()) return;
    const QRect box = p.fontMetrics().boundingRect(area, int(align), text).adjusted(-4, -2, 4, 2);
    p.fillRect(box, QColor(0, 0, 0, 160));
    p.setPen(Qt::white);
    p.drawText(area, int(align), text);
}
}  // namespace

CompareCanvas::CompareCanvas(ViewTransform* transform, QWidget* parent) : QWidget(parent), transform_(transform) {
    setMinimumSize(160, 120);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setMouseTracking(true);  // the probe follows the cursor without a button down
    connect(transform_, &ViewTransform::changed, this, qOverload<>(&QWidget::update));
}

void CompareCanvas::setImages(QImage first, QImage second) {
    first_ = std::move(first);
    second_ = std::move(second);
    update();
}

void CompareCanvas::setCaptions(QString first, QString second) {
    firstCaption_ = std::move(first);
    secondCaption_ = std::move(second);
    update();
}

void CompareCanvas::setLegend(std::optional<Legend> legend) {
    legend_ = std::move(legend);
    update();
}

void CompareCanvas::setDivider(double fraction) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    if (fraction == divider_) return;
    divider_ = fraction;
    update();
    emit dividerMoved(divider_);
}

int CompareCanvas::dividerX() const { return int(std::lround(divider_ * width())); }

QRectF CompareCanvas::imageRect() const {
    return transform_->imageRect(QSizeF(first_.size()), QSizeF(size()));
}

QPointF CompareCanvas::toImage(QPointF pos) const {
    const QRectF r = imageRect();
    if (r.isEmpty()) return {-1, -1};
    return {(pos.x() - r.x()) / r.width(), (pos.y() - r.y()) / r.height()};
}

void CompareCanvas::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), QColor(32, 32, 36));
    if (first_.isNull()) {
        p.setPen(QColor(170, 170, 170));
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, tr("Waiting for the preview and the converged image"));
        return;
    }
    const QRectF target = imageRect();
    // Nearest when enlarging, so that the pixels being compared stay readable.
    p.setRenderHint(QPainter::SmoothPixmapTransform, target.width() < first_.width());
    if (!isSplit()) {
        p.drawImage(target, first_);
        caption(p, rect().adjusted(8, 6, -8, -6), firstCaption_, Qt::AlignLeft | Qt::AlignTop);
    } else {
        const int x = dividerX();
        p.save();
        p.setClipRect(QRect(0, 0, x, height()));
        p.drawImage(target, first_);
        p.setClipRect(QRect(x, 0, width() - x, height()));
        p.drawImage(target, second_);
        p.restore();
        p.setPen(QPen(QColor(255, 255, 255, 220), 1));
        p.drawLine(x, 0, x, height());
        // A handle, so that the divider reads as something to drag.
        p.setBrush(QColor(255, 255, 255, 220));
        p.drawEllipse(QPointF(x + 0.5, height() / 2.0), 5, 5);
        caption(p, QRect(8, 6, std::max(0, x - 16), 20), firstCaption_, Qt::AlignLeft | Qt::AlignTop);
        caption(p, QRect(x + 8, 6, std::max(0, width() - x - 16), 20), secondCaption_, Qt::AlignRight | Qt::AlignTop);
    }
    if (legend_) paintLegend(p, rect(), *legend_);
}

void CompareCanvas::mousePressEvent(QMouseEvent* e) {
    last_ = e->position();
    if (e->button() != Qt::LeftButton && e->button() != Qt::MiddleButton) return;
    drag_ = isSplit() && e->button() == Qt::LeftButton && std::abs(e->position().x() - dividerX()) <= kGrab ? Drag::Divider
                                                                                                          : Drag::Pan;
}

void CompareCanvas::mouseMoveEvent(QMouseEvent* e) {
    const QPointF pos = e->position();
    if (drag_ == Drag::Divider) {
        setDivider(pos.x() / std::max(1, width()));
    } else if (drag_ == Drag::Pan) {
        transform_->panBy(pos - last_, QSizeF(first_.size()), QSizeF(size()));
    } else {
        setCursor(isSplit() && std::abs(pos.x() - dividerX()) <= kGrab ? Qt::SplitHCursor : Qt::CrossCursor);
    }
    last_ = pos;
    emit hovered(toImage(pos));
}

void CompareCanvas::mouseReleaseEvent(QMouseEvent*) { drag_ = Drag::None; }

void CompareCanvas::wheelEvent(QWheelEvent* e) {
    // One notch (120) zooms by 2^(1/4): four notches double the size.
    const double factor = std::exp2(e->angleDelta().y() / 480.0);
    transform_->zoomAbout(factor, e->position(), QSizeF(first_.size()), QSizeF(size()));
    e->accept();
}

void CompareCanvas::leaveEvent(QEvent*) { emit hovered({-1, -1}); }

}  // namespace lucerna
