#pragma once
// What the window's operations tell the user: a line in the status bar for a few seconds, or a
// failure, which stays there until the next line and is kept as lastError() (a menu shows it in a
// message box; tests read it).

#include <QString>

#include <functional>

class QMainWindow;

namespace lucerna {

class WindowMessages {
public:
    explicit WindowMessages(QMainWindow* window) : window_(window) {}

    // A line in the status bar for `ms` milliseconds.
    void show(const QString& text, int ms) const;
    // Returns false, for `return fail(...)` in the operations that say whether they succeeded.
    bool fail(const QString& message);
    QString lastError() const { return lastError_; }
    // Runs `operation`; when it throws, says why as a failure, after `context` and ": " when one
    // is given (e.g. "Could not add FILE"), and returns false.
    bool attempt(const std::function<void()>& operation, const QString& context = {});
    // After a menu's operation: when it did not succeed, a message box titled `title` says
    // lastError().
    void warnUnless(bool succeeded, const QString& title) const;
    // The parent of the operations' dialogs.
    QMainWindow* window() const { return window_; }

private:
    QMainWindow* window_;
    QString lastError_;
};

}  // namespace lucerna
