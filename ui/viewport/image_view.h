#pragma once
// A picture fitted into the widget with its aspect ratio kept, on a dark background. Used by the
// viewport (with overlays and mouse navigation on top) and by the converging render's view. A
// plain QWidget rather than a QOpenGLWidget: the frames are images already, and Qt's offscreen
// platform, which the tests use, cannot run a QOpenGLWidget.

#include "render/display/false_colour.h"

#include <QImage>
#include <QWidget>

namespace lucerna {

class ImageView : public QWidget {
    Q_OBJECT
public:
    explicit ImageView(QWidget* parent = nullptr);

    void setImage(QImage image);
    const QImage& image() const { return image_; }
    // Where the picture is drawn, in widget coordinates (empty before the first image).
    QRectF imageRect() const;
    // Text shown while there is no picture yet.
    void setPlaceholder(const QString& text);
    const QString& placeholder() const { return placeholder_; }
    // A false-colour legend drawn over the picture (when it is false colour).
    void setLegend(std::optional<Legend> legend);

    QSize sizeHint() const override { return {420, 420}; }

protected:
    void paintEvent(QPaintEvent*) override;
    // Overlays drawn over the picture (the viewport's light markers).
    virtual void paintOverlay(QPainter&) {}

private:
    QImage image_;
    QString placeholder_;
    std::optional<Legend> legend_;
};

}  // namespace lucerna
