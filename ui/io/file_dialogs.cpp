#include "ui/io/file_dialogs.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QStandardPaths>

namespace lucerna {

QString suggestedFileName(const QString& scenePath, const QString& extension, const QString& fallback) {
    const QString base = QFileInfo(scenePath).completeBaseName();
    return (base.isEmpty() ? fallback : base) + '.' + extension;
}

FileDialogs::FileDialogs(QWidget* parent, std::function<QString()> sceneFolder)
    : parent_(parent), sceneFolder_(std::move(sceneFolder)) {}

QString FileDialogs::folder() const {
    const QString scene = sceneFolder_();
    if (!scene.isEmpty() && QFileInfo(scene).isDir()) return scene;
    if (!lastFolder_.isEmpty() && QFileInfo(lastFolder_).isDir()) return lastFolder_;
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return QFileInfo(documents).isDir() ? documents : QDir::homePath();
}

QString FileDialogs::open(const QString& caption, const QString& filter) { return ask(Mode::Open, caption, filter); }
QString FileDialogs::save(const QString& caption, const QString& filter, const QString& suggestedName) {
    return ask(Mode::Save, caption, filter, suggestedName);
}

QString FileDialogs::ask(Mode mode, const QString& caption, const QString& filter, const QString& suggestedName) {
    const QString start = suggestedName.isEmpty() ? folder() : QDir(folder()).filePath(suggestedName);
    QString path;
    if (ask_) path = ask_(mode, caption, start, filter);
    else if (mode == Mode::Open) path = QFileDialog::getOpenFileName(parent_, caption, start, filter);
    else path = QFileDialog::getSaveFileName(parent_, caption, start, filter);
    if (!path.isEmpty()) lastFolder_ = QFileInfo(path).absolutePath();
    return path;
}

}  // namespace lucerna
