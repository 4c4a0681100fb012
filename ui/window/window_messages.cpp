#include "ui/window/window_messages.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QStatusBar>

namespace lucerna {

void WindowMessages::show(const QString& text, int ms) const { window_->statusBar()->showMessage(text, ms); }

bool WindowMessages::fail(const QString& message) {
    lastError_ = message;
    window_->statusBar()->showMessage(message);
    return false;
}

bool WindowMessages::attempt(const std::function<void()>& operation, const QString& context) {
    try {
        operation();
    } catch (const std::exception& e) {
        const QString why = QString::fromStdString(e.what());
        return fail(context.isEmpty() ? why : context + QStringLiteral(": ") + why);
    }
    return true;
}

void WindowMessages::warnUnless(bool succeeded, const QString& title) const {
    if (!succeeded) QMessageBox::warning(window_, title, lastError_);
}

}  // namespace lucerna
