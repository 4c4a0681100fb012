#include "ui/window/wheel_guard.h"

#include <QAbstractScrollArea>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QScrollBar>
#include <QWheelEvent>

namespace lucerna {

namespace {
void takeWheelFocus(QWidget* w) {
    if (w->focusPolicy() == Qt::WheelFocus) w->setFocusPolicy(Qt::StrongFocus);
}
}  // namespace

WheelGuard::WheelGuard(QObject* parent) : QObject(parent) {
    qApp->installEventFilter(this);
    for (QWidget* w : QApplication::allWidgets())
        if (guards(w)) takeWheelFocus(w);
}

bool WheelGuard::guards(const QWidget* w) {
    if (!w || qobject_cast<const QScrollBar*>(w)) return false;  // scrolling is no edit
    return qobject_cast<const QAbstractSpinBox*>(w) || qobject_cast<const QComboBox*>(w) ||
           qobject_cast<const QAbstractSlider*>(w);
}

bool WheelGuard::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::Polish && event->type() != QEvent::Wheel) return false;
    auto* w = qobject_cast<QWidget*>(watched);
    if (!guards(w)) return false;
    // Fields made after the guard: before their first showing (the wheel focus must go before
    // the first wheel event, as QApplication gives the focus ahead of any filter).
    takeWheelFocus(w);
    if (event->type() == QEvent::Polish || w->hasFocus()) return false;
    auto* wheel = static_cast<QWheelEvent*>(event);
    if (scrollAround(w, wheel)) return true;
    // No panel to scroll: the field keeps its value, and the window's own handling (a parent
    // that scrolls) may still take the event.
    event->ignore();
    return true;
}

bool WheelGuard::scrollAround(QWidget* field, QWheelEvent* wheel) {
    for (QWidget* p = field->parentWidget(); p; p = p->parentWidget()) {
        auto* area = qobject_cast<QAbstractScrollArea*>(p);
        // A combo box's list is a scroll area too, but not one the field stands in.
        if (!area || !area->viewport()->isAncestorOf(field)) continue;
        QWidget* viewport = area->viewport();
        const QPointF at = field->mapTo(viewport, wheel->position());
        QWheelEvent forwarded(at, wheel->globalPosition(), wheel->pixelDelta(), wheel->angleDelta(), wheel->buttons(),
                              wheel->modifiers(), wheel->phase(), wheel->inverted(), wheel->source());
        QApplication::sendEvent(viewport, &forwarded);
        return true;
    }
    return false;
}

}  // namespace lucerna
