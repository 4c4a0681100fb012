#pragma once
// One pane of the comparison: a picture under a shared zoom and pan (ViewTransform), or two
// pictures split by a vertical divider that the user drags (left of it the first, right of it the
// second), with an optional false-colour legend. Wheel zooms about the cursor, a drag pans, and
// the cursor's image point is reported for the pixel probe.

#include "render/display/false_colour.h"

#include <QImage>
#include <QWidget>

#include <optional>

namespace lucerna {

class ViewTransform;

class CompareCanvas : public QWidget {
    Q_OBJECT
public:
    CompareCanvas(ViewTransform* transform, QWidget* parent = nullptr);

    // One picture (second null), or a split of two.
    void setImages(QImage first, QImage second = {});
    void setCaptions(QString first, QString second = {});
    void setLegend(std::optional<Legend> legend);
    const std::optional<Legend>& legend() const { return legend_; }

    // The divider's position as a fraction of the widget's width (split only).
    double divider() const { return divider_; }
    void setDivider(double fraction);
    int dividerX() const;
    bool isSplit() const { return !second_.isNull(); }

    // Where the pictures are drawn, in widget coordinates.
    QRectF imageRect() const;
    // The normalised image point (0..1) under a widget position.
    QPointF toImage(QPointF widgetPos) const;

    QSize sizeHint() const override { return {420, 320}; }

signals:
    // The normalised image point under the cursor; outside the image when it leaves it.
    void hovered(QPointF imagePoint);
    void dividerMoved(double fraction);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent*) override;
    void mouseMoveEvent(QMouseEvent*) override;
    void mouseReleaseEvent(QMouseEvent*) override;
    void wheelEvent(QWheelEvent*) override;
    void leaveEvent(QEvent*) override;

private:
    enum class Drag { None, Pan, Divider };
    ViewTransform* transform_;
    QImage first_, second_;
    QString firstCaption_, secondCaption_;
    std::optional<Legend> legend_;
    double divider_ = 0.5;
    Drag drag_ = Drag::None;
    QPointF last_;
};

}  // namespace lucerna
