#pragma once
// The zoom and pan that several canvases share, so that the preview and the converged image
// stay on the same spot while the user looks around (side by side, split). Kept in normalised
// image coordinates (0..1 on both axes), not pixels: the preview and the converged image have
// different resolutions but show the same camera.

#include <QObject>
#include <QPointF>
#include <QRectF>
#include <QSizeF>

namespace lucerna {

class ViewTransform : public QObject {
    Q_OBJECT
public:
    explicit ViewTransform(QObject* parent = nullptr) : QObject(parent) {}

    // 1 = the whole image fitted into the widget.
    double zoom() const { return zoom_; }
    // The normalised image point at the widget's centre.
    QPointF centre() const { return centre_; }
    void set(double zoom, QPointF centre);
    void reset() { set(1.0, {0.5, 0.5}); }

    // Where an image of aspect `imageSize` is drawn in a widget of `widgetSize`.
    QRectF imageRect(QSizeF imageSize, QSizeF widgetSize) const;
    // Zoom by `factor` keeping the image point under `anchor` (widget coordinates) in place.
    void zoomAbout(double factor, QPointF anchor, QSizeF imageSize, QSizeF widgetSize);
    // Move the image by `delta` widget pixels.
    void panBy(QPointF delta, QSizeF imageSize, QSizeF widgetSize);

signals:
    void changed();

private:
    double zoom_ = 1.0;
    QPointF centre_{0.5, 0.5};
};

}  // namespace lucerna
