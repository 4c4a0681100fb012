#pragma once
// Scroll wheels scroll, and never edit by accident: over a spin box, a combo box or a slider that
// does not have the keyboard focus, the wheel scrolls the panel the field stands in (the nearest
// scroll area around it, a dock's) instead of changing the field's value. A field with the
// focus (clicked or tabbed into) takes the wheel as before. Fields stop taking the focus from
// the wheel itself (Qt::WheelFocus becomes Qt::StrongFocus), or the first wheel step would focus
// the field and the next ones edit it.

#include <QObject>

class QWheelEvent;
class QWidget;

namespace lucerna {

class WheelGuard : public QObject {
    Q_OBJECT
public:
    // Watches every widget of the application while it lives (an application event filter), and
    // takes the wheel focus from the guarded fields that exist already.
    explicit WheelGuard(QObject* parent = nullptr);

    // Whether `w` is a field the wheel would edit (spin box, combo box, slider; not a scroll bar).
    static bool guards(const QWidget* w);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    // The wheel turned over `field` sent to the scroll area around it; false when there is none.
    static bool scrollAround(QWidget* field, QWheelEvent* wheel);
};

}  // namespace lucerna
