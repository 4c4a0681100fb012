#include "ui/compare/view_transform.h"

#include <algorithm>

namespace lucerna {

void ViewTransform::set(double zoom, QPointF centre) {
    // Past 64x a pixel fills the screen; below 1/4 the image is a stamp.
    zoom = std::clamp(zoom, 0.25, 64.0);
    centre = QPointF(std::clamp(centre.x(), 0.0, 1.0), std::clamp(centre.y(), 0.0, 1.0));
    if (zoom == zoom_ && centre == centre_) return;
    zoom_ = zoom;
    centre_ = centre;
    emit changed();
}

QRectF ViewTransform::imageRect(QSizeF imageSize, QSizeF widgetSize) const {
    if (imageSize.isEmpty() || widgetSize.isEmpty()) return {};
    const QSizeF size = imageSize.scaled(widgetSize, Qt::KeepAspectRatio) * zoom_;
    const QPointF topLeft(widgetSize.width() / 2 - centre_.x() * size.width(),
                          widgetSize.height() / 2 - centre_.y() * size.height());
    return {topLeft, size};
}

void ViewTransform::zoomAbout(double factor, QPointF anchor, QSizeF imageSize, QSizeF widgetSize) {
    const QRectF r = imageRect(imageSize, widgetSize);
    if (r.isEmpty()) return;
    const QPointF p((anchor.x() - r.x()) / r.width(), (anchor.y() - r.y()) / r.height());
    const double zoom = std::clamp(zoom_ * factor, 0.25, 64.0);
    const QSizeF size = imageSize.scaled(widgetSize, Qt::KeepAspectRatio) * zoom;
    // Solve for the centre that puts p back under the anchor.
    set(zoom, QPointF(p.x() - (anchor.x() - widgetSize.width() / 2) / size.width(),
                      p.y() - (anchor.y() - widgetSize.height() / 2) / size.height()));
}

void ViewTransform::panBy(QPointF delta, QSizeF imageSize, QSizeF widgetSize) {
    const QRectF r = imageRect(imageSize, widgetSize);
    if (r.isEmpty()) return;
    set(zoom_, centre_ - QPointF(delta.x() / r.width(), delta.y() / r.height()));
}

}  // namespace lucerna
