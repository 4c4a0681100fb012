#include "core/atomic_file.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryFile>

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace lucerna {

namespace {

// A writer killed outright (SIGKILL, a power cut) leaves its ".NAME.XXXXXX.part" behind. Each
// writer holds an exclusive flock on its temporary for as long as it writes (the kernel drops
// it when the process dies), so a temporary of the same target that can be locked belongs to
// nobody and is removed; one that is locked is another writer's, at work, and is left alone.
void removeStaleTemporaries(const QFileInfo& target) {
    const QString prefix = "." + target.fileName() + ".";
    const QDir dir = target.absoluteDir();
    for (const QString& name : dir.entryList({prefix + "*.part"}, QDir::Files | QDir::Hidden | QDir::System)) {
        if (name.size() != prefix.size() + 6 + 5 || !name.startsWith(prefix)) continue;  // XXXXXX: 6 characters
        const std::string stale = dir.filePath(name).toStdString();
        const int fd = ::open(stale.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) continue;
        if (::flock(fd, LOCK_EX | LOCK_NB) == 0) ::unlink(stale.c_str());
        ::close(fd);
    }
}

}  // namespace

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    const QFileInfo target(QString::fromStdString(path));
    removeStaleTemporaries(target);
    // QTemporaryFile reserves a unique name in the target's folder (same file system, so the
    // rename is atomic); the writer then replaces its content by name. The reservation stays
    // open, locked, until the rename (see removeStaleTemporaries).
    QTemporaryFile reserve(target.absoluteDir().filePath(QStringLiteral(".%1.XXXXXX.part").arg(target.fileName())));
    if (!reserve.open())
        throw std::runtime_error("cannot create a file in " + target.absolutePath().toStdString() + ": " +
                                 reserve.errorString().toStdString());
    ::flock(reserve.handle(), LOCK_EX | LOCK_NB);
    const std::string temp = reserve.fileName().toStdString();
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
    reserve.close();  // after the rename: the name is the target's now, and the lock goes
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
