#include "ui/window/layout_state.h"

#include <QDockWidget>
#include <QEvent>
#include <QMainWindow>
#include <QSettings>
#include <QTimer>

namespace lucerna {

LayoutState::LayoutState(QMainWindow* window, QWidget* viewport, std::function<void()> defaultSizes)
    : QObject(window), window_(window), viewport_(viewport), defaultSizes_(std::move(defaultSizes)),
      defaultState_(window->saveState()) {
    window_->installEventFilter(this);
}

void LayoutState::restore() {
    QSettings settings;
    window_->restoreGeometry(settings.value("window/geometry").toByteArray());
    if (!window_->restoreState(settings.value("window/state").toByteArray())) {
        // First start. Dock sizes only take once the window has its layout: after a turn of the loop.
        QTimer::singleShot(0, this, [this] { defaultSizes_(); });
        return;
    }
    checkPending_ = true;
    if (window_->isVisible()) QTimer::singleShot(0, this, [this] { checkViewportRoom(); });
}

void LayoutState::save() const {
    QSettings settings;
    settings.setValue("window/geometry", window_->saveGeometry());
    settings.setValue("window/state", window_->saveState());
}

void LayoutState::reset() {
    window_->restoreState(defaultState_);
    for (QDockWidget* d : window_->findChildren<QDockWidget*>()) {
        d->setFloating(false);
        d->show();
    }
    // The tabs in front as at the first start: the state names no current tab.
    if (auto* render = window_->findChild<QDockWidget*>("renderDock")) render->raise();
    defaultSizes_();
}

bool LayoutState::eventFilter(QObject* watched, QEvent* event) {
    // The layout has its sizes once the window is shown.
    if (watched == window_ && event->type() == QEvent::Show && checkPending_)
        QTimer::singleShot(0, this, [this] { checkViewportRoom(); });
    return false;
}

void LayoutState::checkViewportRoom() {
    if (!checkPending_ || !window_->isVisible()) return;
    checkPending_ = false;
    if (viewport_->width() < kMinViewportShare * window_->width()) reset();
}

}  // namespace lucerna
