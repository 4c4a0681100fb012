#pragma once
// File > New, Open, Open Recent, Save and Save As on the window's document, the question asked
// before unsaved changes are lost, and crash recovery (ui/document/autosave.h).

#include "ui/document/document.h"

#include <QMessageBox>
#include <QObject>

#include <functional>
#include <memory>

class QMenu;

namespace lucerna {

class Autosave;
class ConvergingRender;
class FileDialogs;
class RecentFilesMenu;
class WindowMessages;

class FileActions : public QObject {
    Q_OBJECT
public:
    // The converging render starts over on each scene opened; the recent files' menu is a child
    // of the messages' window.
    FileActions(Document& doc, ConvergingRender& render, FileDialogs& dialogs, WindowMessages& messages);
    ~FileActions() override;

    // Adds New, Open, Open Recent, Save and Save As to `menu`.
    void addTo(QMenu* menu);

    // The operations behind the menu, without dialogs. Each returns false and says why
    // (WindowMessages::fail) when it fails.
    // Autosaves unsaved changes (secureUnsavedWork) before it reads the file.
    bool openFile(const QString& path);
    bool save();  // to the document's path; Save As when it has none
    bool saveFileAs(const QString& path);
    // File > New without its question: an untitled scene with a floor (ui/document/new_scene.h).
    void newScene();
    // The document becomes `scene`, from the file at `path` ("": untitled), with no undo history;
    // `unsaved`: its content is unsaved work (an import, a recovery). The converging render starts
    // on it, and the recovery file of the scene before goes (its changes were saved or let go).
    void replaceScene(Scene scene, const std::string& path, bool unsaved);

    // Before a read that could crash its reader (a third-party importer) or replace the scene:
    // unsaved changes go to the recovery file at once, so that a crash loses none of them.
    void secureUnsavedWork();

    // Before unsaved changes are lost: asks (Save, Discard, Cancel); true when it may go on.
    bool maybeSave();
    // Replaces the question maybeSave() asks (tests answer without a modal dialog).
    void setSaveQuestion(std::function<QMessageBox::StandardButton()> ask) { askSave_ = std::move(ask); }

    // Autosaves go to `directory` from now on; a recovery file a previous session left there is
    // offered back (the question is replaceable for tests, like the save question). Returns true
    // when the scene was recovered.
    bool startAutosave(const QString& directory, int intervalMs);
    void setRecoveryQuestion(std::function<QMessageBox::StandardButton()> ask) { askRecovery_ = std::move(ask); }
    Autosave* autosave() const { return autosave_.get(); }
    // The window closes with its changes saved or let go: nothing to recover.
    void closedCleanly();

    RecentFilesMenu* recentFiles() const { return recent_; }

private:
    Document& doc_;
    ConvergingRender& render_;
    FileDialogs& dialogs_;
    WindowMessages& messages_;
    RecentFilesMenu* recent_;
    std::function<QMessageBox::StandardButton()> askSave_, askRecovery_;
    std::unique_ptr<Autosave> autosave_;
};

}  // namespace lucerna
