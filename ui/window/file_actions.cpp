#include "ui/window/file_actions.h"

#include "core/scene/scene_io.h"
#include "ui/document/autosave.h"
#include "ui/document/new_scene.h"
#include "ui/io/file_dialogs.h"
#include "core/read_crash_hook.h"
#include "ui/rendering/converging_render.h"
#include "ui/window/menu_entry.h"
#include "ui/window/recent_files.h"
#include "ui/window/window_messages.h"

#include <QDir>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>

#include <filesystem>

namespace lucerna {

FileActions::FileActions(Document& doc, ConvergingRender& render, FileDialogs& dialogs, WindowMessages& messages)
    : doc_(doc), render_(render), dialogs_(dialogs), messages_(messages) {
    recent_ = new RecentFilesMenu(
        [this](const QString& path) {
            if (maybeSave()) messages_.warnUnless(openFile(path), tr("Open scene"));
        },
        messages.window());
}

FileActions::~FileActions() = default;

void FileActions::addTo(QMenu* menu) {
    addMenuEntry(menu, tr("&New"), "actionNew", QKeySequence(tr("Ctrl+N")), this, [this] {
        if (maybeSave()) newScene();
    });
    addMenuEntry(menu, tr("&Open..."), "actionOpen", QKeySequence(tr("Ctrl+O")), this, [this] {
        if (!maybeSave()) return;
        const QString path = dialogs_.open(tr("Open scene"), tr("Lucerna scenes (*.json)"));
        if (!path.isEmpty()) messages_.warnUnless(openFile(path), tr("Open scene"));
    });
    menu->addMenu(recent_);
    addMenuEntry(menu, tr("&Save"), "actionSave", QKeySequence(tr("Ctrl+S")), this, [this] {
        const bool saved = save();
        messages_.warnUnless(saved || messages_.lastError().isEmpty(), tr("Save scene"));
    });
    addMenuEntry(menu, tr("Save &As..."), "actionSaveAs", QKeySequence(tr("Ctrl+Shift+S")), this, [this] {
        const QString path = dialogs_.save(tr("Save scene"), tr("Lucerna scenes (*.json)"));
        if (!path.isEmpty()) messages_.warnUnless(saveFileAs(path), tr("Save scene"));
    });
}

void FileActions::replaceScene(Scene scene, const std::string& path, bool unsaved) {
    doc_.reset(std::move(scene));
    doc_.setPath(path);
    if (unsaved) doc_.undoStack()->resetClean();
    render_.start();
    if (autosave_) autosave_->discard();
}

bool FileActions::openFile(const QString& path) {
    secureUnsavedWork();
    Scene scene;
    if (!messages_.attempt([&] {
            crashHereWhenTesting("open");
            scene = loadScene(path.toStdString());
        }))
        return false;
    replaceScene(std::move(scene), QFileInfo(path).absoluteFilePath().toStdString(), false);
    recent_->add(path);
    messages_.show(tr("Opened %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

void FileActions::newScene() {
    replaceScene(newSceneWithFloor(dialogs_.folder().toStdString()), {}, false);
    messages_.show(tr("New scene"), 5000);
}

bool FileActions::save() {
    if (doc_.path().empty()) {
        const QString path = dialogs_.save(tr("Save scene"), tr("Lucerna scenes (*.json)"));
        return !path.isEmpty() && saveFileAs(path);
    }
    return saveFileAs(QString::fromStdString(doc_.path()));
}

bool FileActions::saveFileAs(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    // Mesh files are named relative to the scene's folder: rebase them on the new folder, so that
    // the saved file finds the same meshes.
    Scene scene = doc_.scene();
    const QDir newDir = QFileInfo(absolute).absoluteDir();
    for (Object& o : scene.objects)
        if (o.mesh.kind == MeshSource::Kind::File && !std::filesystem::path(o.mesh.file).is_absolute()) {
            const QString meshPath = QDir(QString::fromStdString(scene.baseDir)).absoluteFilePath(QString::fromStdString(o.mesh.file));
            o.mesh.file = newDir.relativeFilePath(meshPath).toStdString();
        }
    if (!messages_.attempt([&] { saveScene(scene, absolute.toStdString()); }, tr("Could not save %1").arg(path)))
        return false;
    if (newDir.absolutePath() != QDir(QString::fromStdString(doc_.scene().baseDir)).absolutePath()) {
        // Reload so that the document's folder and mesh paths are the saved file's. Not undoable
        // across the save, as in any editor after Save As to another folder.
        if (!openFile(absolute)) return false;
    } else {
        doc_.setPath(absolute.toStdString());
        doc_.markSaved();
    }
    if (autosave_) autosave_->discard();
    recent_->add(absolute);
    messages_.show(tr("Saved %1").arg(QFileInfo(path).fileName()), 5000);
    return true;
}

void FileActions::secureUnsavedWork() {
    if (autosave_) autosave_->writeNow();
}

bool FileActions::maybeSave() {
    if (!doc_.isModified()) return true;
    const QMessageBox::StandardButton answer =
        askSave_ ? askSave_()
                 : QMessageBox::warning(messages_.window(), tr("Unsaved changes"), tr("The scene has unsaved changes. Save them?"),
                                        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    if (answer != QMessageBox::Discard) return false;
    if (autosave_) autosave_->letGo();
    return true;
}

bool FileActions::startAutosave(const QString& directory, int intervalMs) {
    QString error;
    std::optional<Autosave::Recovery> recovery = Autosave::pending(directory, &error);
    if (!error.isEmpty()) messages_.fail(tr("A recovery file could not be read: %1").arg(error));
    bool recovered = false;
    if (recovery) {
        const QString name = recovery->documentPath.empty() ? tr("an untitled scene")
                                                            : QString::fromStdString(recovery->documentPath);
        const QMessageBox::StandardButton answer =
            askRecovery_ ? askRecovery_()
                         : QMessageBox::question(messages_.window(), tr("Recover unsaved changes"),
                                                 tr("Lucerna did not close cleanly. Recover the unsaved changes to %1?")
                                                     .arg(name),
                                                 QMessageBox::Yes | QMessageBox::No);
        if (answer == QMessageBox::Yes) {
            replaceScene(std::move(recovery->scene), recovery->documentPath, true);
            messages_.show(tr("Recovered the unsaved changes to %1").arg(name), 5000);
            recovered = true;
        }
        Autosave::discard(directory);
    }
    autosave_ = std::make_unique<Autosave>(doc_, directory, intervalMs);
    return recovered;
}

void FileActions::closedCleanly() {
    if (autosave_) autosave_->closedCleanly();
}

}  // namespace lucerna
