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

}  // namespace lucerna
