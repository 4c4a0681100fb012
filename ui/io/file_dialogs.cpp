#include "ui/io/file_dialogs.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QStandardPaths>

namespace lucerna {

FileDialogs::FileDialogs(QWidget* parent, std::function<QString()> sceneFolder)
    : parent_(parent), sceneFolder_(std::move(sceneFolder)) {}

QString FileDialogs::folder() const {
    const QString scene = sceneFolder_();
    if (!scene.isEmpty() && QFileInfo(scene).isDir()) return scene;
    if (!lastFolder_.isEmpty()) return lastFolder_;
    return QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
}

QString FileDialogs::open(const QString& caption, const QString& filter) { return ask(Mode::Open, caption, filter); }
QString FileDialogs::save(const QString& caption, const QString& filter) { return ask(Mode::Save, caption, filter); }

QString FileDialogs::ask(Mode mode, const QString& caption, const QString& filter) {
    const QString start = folder();
    QString path;
    if (ask_) path = ask_(mode, caption, start, filter);
    else if (mode == Mode::Open) path = QFileDialog::getOpenFileName(parent_, caption, start, filter);
    else path = QFileDialog::getSaveFileName(parent_, caption, start, filter);
    if (!path.isEmpty()) lastFolder_ = QFileInfo(path).absolutePath();
    return path;
}

}  // namespace lucerna
