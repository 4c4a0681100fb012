#include "core/resources.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <cstdlib>

namespace lucerna {

std::string resourceDirectory() {
    if (const char* env = std::getenv("LUCERNA_RESOURCE_DIR"); env && *env && QFileInfo(env).isDir()) return env;
    // applicationDirPath needs a QCoreApplication; without one only the compiled-in path remains.
    if (QCoreApplication::instance()) {
        const QString installed = QDir(QCoreApplication::applicationDirPath()).absoluteFilePath("../share/lucerna");
        if (QFileInfo(installed + "/scenes").isDir()) return QDir::cleanPath(installed).toStdString();
    }
    return LUCERNA_RESOURCE_DIR;
}

std::string cacheDirectory(const std::string& name) {
    QString base;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) base = QString::fromLocal8Bit(xdg);
    else if (const char* home = std::getenv("HOME"); home && *home) base = QString::fromLocal8Bit(home) + "/.cache";
    else return {};
    const QString path = base + "/lucerna/" + QString::fromStdString(name);
    return QDir().mkpath(path) ? path.toStdString() : std::string();
}

}  // namespace lucerna
