#pragma once
// The file dialogs of the window's menus. They open in the scene's folder (the document's, or the
// folder the last dialog ended in for an untitled scene), and tests replace the question with an
// answer of their own, as they do the save question.

#include <QString>

#include <functional>

class QWidget;

namespace lucerna {

// The file name a save dialog offers for what is made from the scene at `scenePath`: the scene's
// base name with `extension` ("office_floor.pdf"), or `fallback` with it for an untitled scene.
QString suggestedFileName(const QString& scenePath, const QString& extension, const QString& fallback);

class FileDialogs {
public:
    enum class Mode { Open, Save };
    // caption, where the dialog opens (the folder; for a save with a suggested name, that name
    // in the folder), the name filter; returns the chosen path or "".
    using Ask = std::function<QString(Mode mode, const QString& caption, const QString& folder, const QString& filter)>;

    // `sceneFolder` gives the open document's folder ("" for an untitled scene, or one whose
    // folder is not the user's: the bundled scenes').
    FileDialogs(QWidget* parent, std::function<QString()> sceneFolder);

    QString open(const QString& caption, const QString& filter);
    // `suggestedName`: the file name the save dialog offers ("" for none); never a folder's name,
    // which Qt's dialog would put in the name field when given a folder that does not exist.
    QString save(const QString& caption, const QString& filter, const QString& suggestedName = {});
    void replace(Ask ask) { ask_ = std::move(ask); }
    // Where the next dialog opens: a folder that exists (the scene's, the last dialog's, the
    // user's documents, else home).
    QString folder() const;

private:
    QString ask(Mode mode, const QString& caption, const QString& filter, const QString& suggestedName = {});

    QWidget* parent_;
    std::function<QString()> sceneFolder_;
    Ask ask_;
    QString lastFolder_;
};

}  // namespace lucerna
