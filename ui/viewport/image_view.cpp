#include "ui/viewport/image_view.h"

#include <QPainter>

namespace lucerna {

ImageView::ImageView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(160, 120);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void ImageView::setImage(QImage image) {
    image_ = std::move(image);
    update();
}

void ImageView::setPlaceholder(const QString& text) {
    placeholder_ = text;
    update();
}

void ImageView::setLegend(std::optional<Legend> legend) {
    legend_ = std::move(legend);
    update();
}

QRectF ImageView::imageRect() const {
    if (image_.isNull()) return {};
    const QSizeF fitted = QSizeF(image_.size()).scaled(QSizeF(size()), Qt::KeepAspectRatio);
    return QRectF(QPointF((width() - fitted.width()) / 2, (height() - fitted.height()) / 2), fitted);
}

void ImageView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(32, 32, 36));
    if (image_.isNull()) {
        painter.setPen(QColor(170, 170, 170));
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, placeholder_);
        return;
    }
    // Smooth when shrinking; nearest when enlarging, so that pixels stay readable.
    const QRectF target = imageRect();
    painter.setRenderHint(QPainter::SmoothPixmapTransform, target.width() < image_.width());
    painter.drawImage(target, image_);
    paintOverlay(painter);
    if (legend_) paintLegend(painter, rect(), *legend_);
}

}  // namespace lucerna
