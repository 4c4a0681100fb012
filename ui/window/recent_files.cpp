#include "ui/window/recent_files.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace lucerna {

namespace {
const char* kKey = "recentFiles";
}

RecentFilesMenu::RecentFilesMenu(std::function<void(const QString&)> open, QWidget* parent)
    : QMenu(tr("Open &Recent"), parent), open_(std::move(open)) {
    setObjectName("menuRecentFiles");
    rebuild();
}

QStringList RecentFilesMenu::files() const { return QSettings().value(kKey).toStringList(); }

void RecentFilesMenu::add(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList list = files();
    list.removeAll(absolute);
    list.prepend(absolute);
    while (list.size() > kMaxFiles) list.removeLast();
    QSettings().setValue(kKey, list);
    rebuild();
}

void RecentFilesMenu::rebuild() {
    clear();
    const QStringList list = files();
    for (int i = 0; i < list.size(); ++i) {
        const QString path = list[i];
        QAction* a = addAction(QString("&%1 %2").arg(i + 1).arg(QDir::toNativeSeparators(path)));
        a->setObjectName(QString("actionRecent%1").arg(i + 1));
        connect(a, &QAction::triggered, this, [this, path] { open_(path); });
    }
    setEnabled(!list.isEmpty());
}

}  // namespace lucerna
