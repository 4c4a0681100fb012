#include "core/atomic_file.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryFile>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace lucerna {

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    const QFileInfo target(QString::fromStdString(path));
    // QTemporaryFile reserves a unique name in the target's folder (same file system, so the
    // rename is atomic); the writer then replaces its content by name.
    QTemporaryFile reserve(target.absoluteDir().filePath(QStringLiteral(".%1.XXXXXX.part").arg(target.fileName())));
    if (!reserve.open())
        throw std::runtime_error("cannot create a file in " + target.absolutePath().toStdString() + ": " +
                                 reserve.errorString().toStdString());
    const std::string temp = reserve.fileName().toStdString();
    reserve.close();
    try {
        write(temp);
    } catch (...) {
        std::remove(temp.c_str());
        throw;
    }
    reserve.setAutoRemove(false);
    // QTemporaryFile creates 0600; a rendered image should be readable like any other file.
    QFile::setPermissions(QString::fromStdString(temp),
                          QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup | QFile::ReadOther);
    if (std::rename(temp.c_str(), target.absoluteFilePath().toStdString().c_str()) != 0) {
        std::remove(temp.c_str());
        throw std::runtime_error("cannot rename " + temp + " to " + path);
    }
}

void writeTextAtomically(const std::string& path, const std::string& text) {
    writeAtomically(path, [&](const std::string& temp) {
        std::ofstream f(temp, std::ios::binary);
        f << text;
        f.close();
        if (!f) throw std::runtime_error(path + ": cannot write");
    });
}

}  // namespace lucerna
