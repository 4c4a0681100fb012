#include "ui/window/menu_entry.h"

#include <QMenu>

namespace lucerna {

QAction* addMenuEntry(QMenu* menu, const QString& text, const QString& name, const QKeySequence& shortcut,
                      const QObject* context, std::function<void()> triggered) {
    QAction* a = menu->addAction(text, context, std::move(triggered));
    a->setObjectName(name);
    a->setShortcut(shortcut);
    return a;
}

}  // namespace lucerna
