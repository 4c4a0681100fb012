#pragma once
// Driving the application's window from tests as a user would: the bundled scene and copies of
// it, menu actions, typed values, mouse events, named child widgets and the live preview's frame.

#include "ui/rendering/live_preview.h"
#include "ui/window/main_window.h"

#include <QAction>
#include <QApplication>
#include <QColor>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardPaths>
#include <QString>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>

namespace lucerna::test {

// QSettings, autosaves and the like go to a test location under this application name, never
// to the user's, and every run starts from the first-start layout.
inline void useTestSettings(const char* applicationName) {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("LucernaTest");
    QCoreApplication::setApplicationName(applicationName);
    QSettings().clear();
}

inline QString cornellPath() { return QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/cornell-box.json"); }

// A writable copy of the Cornell box named `name` in `dir` (any older one replaced); empty if it
// could not be made.
inline QString copyOfCornell(const QTemporaryDir& dir, const QString& name) {
    const QString path = dir.filePath(name);
    QFile::remove(path);
    if (!QFile::copy(cornellPath(), path)) return {};
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
    return path;
}

// The live preview's frame of exactly the document's current snapshot, after waiting up to
// `timeoutMs` (generous for a loaded machine, never a timing assertion); null if none came.
inline std::shared_ptr<const LiveFrame> previewOfCurrent(MainWindow& w, int timeoutMs = 30000) {
    const SceneSnapshot want = w.document()->snapshot();
    const auto ok = [&] { return w.livePreview()->frame() && w.livePreview()->frame()->scene == want; };
    if (!QTest::qWaitFor(ok, timeoutMs)) return nullptr;
    return w.livePreview()->frame();
}

// Saves what `w` shows as the PNG `name` (in the test's working folder), after the posted events:
// rows just shown or hidden take their places first.
inline void screenshot(QWidget& w, const QString& name) {
    QCoreApplication::processEvents();
    QVERIFY(w.grab().save(name));
}

// Triggers the window's action of that object name; fails the test when it is missing or disabled.
inline void trigger(MainWindow& w, const char* name) {
    auto* action = w.findChild<QAction*>(name);
    QVERIFY2(action, name);
    QVERIFY2(action->isEnabled(), name);
    action->trigger();
}

// Types a value into a spin box as a designer types it, then Tab (Return would press a dialog's
// default button).
inline void typeAndTab(QAbstractSpinBox* spin, double value) {
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QString::number(value));
    QTest::keyClick(spin, Qt::Key_Tab);
}

// Types a value into a spin box and presses Enter.
inline void typeInto(QDoubleSpinBox* spin, double value) {
    spin->setFocus();
    spin->selectAll();
    QTest::keyClicks(spin, QString::number(value));
    QTest::keyClick(spin, Qt::Key_Return);
}

inline void sendMouse(QWidget* w, QEvent::Type type, QPointF pos, Qt::MouseButton button, Qt::MouseButtons buttons,
                      Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QMouseEvent e(type, pos, w->mapToGlobal(pos), button, buttons, modifiers);
    QApplication::sendEvent(w, &e);
}

// A left click (press and release, no move) at a widget position.
inline void click(QWidget* w, QPointF pos, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    sendMouse(w, QEvent::MouseButtonPress, pos, Qt::LeftButton, Qt::LeftButton, modifiers);
    sendMouse(w, QEvent::MouseButtonRelease, pos, Qt::LeftButton, Qt::NoButton, modifiers);
}

// The child widget of that object name; aborts the test run when there is none.
template <class T>
T* child(QObject& parent, const char* name) {
    T* w = parent.findChild<T*>(name);
    if (!w) qFatal("no widget %s", name);
    return w;
}

// The sum of the channels' differences (0 to 765).
inline double colourDistance(const QColor& a, const QColor& b) {
    return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue());
}

// The smallest colourDistance between `want` and a pixel within `radius` of p.
inline double nearestColour(const QImage& image, QPointF p, const QColor& want, int radius = 1) {
    double best = 1e9;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            const QPoint q(int(std::lround(p.x())) + dx, int(std::lround(p.y())) + dy);
            if (image.rect().contains(q)) best = std::min(best, colourDistance(image.pixelColor(q), want));
        }
    return best;
}

}  // namespace lucerna::test
