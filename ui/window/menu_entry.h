#pragma once
// A menu entry as the window's menus make them: its objectName (tests find an action by it) and
// its shortcut set with it.

#include <QKeySequence>
#include <QString>

#include <functional>

class QAction;
class QMenu;
class QObject;

namespace lucerna {

// `triggered` runs while `context` lives.
QAction* addMenuEntry(QMenu* menu, const QString& text, const QString& name, const QKeySequence& shortcut,
                      const QObject* context, std::function<void()> triggered);

}  // namespace lucerna
