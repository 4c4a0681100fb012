#pragma once
// The file dialogs of the window's menus. They open in the scene's folder (the document's, or the
// folder the last dialog ended in for an untitled scene), and tests replace the question with an
// answer of their own, as they do the save question.

#include <QString>

#include <functional>

class QWidget;

namespace lucerna {

class FileDialogs {
public:
    enum class Mode { Open, Save };
    // caption, the folder the dialog opens in, the name filter; returns the chosen path or "".
    using Ask = std::function<QString(Mode mode, const QString& caption, const QString& folder, const QString& filter)>;

    // `sceneFolder` gives the open document's folder ("" for an untitled scene, or one whose
    // folder is not the user's: the bundled scenes').
    FileDialogs(QWidget* parent, std::function<QString()> sceneFolder);

    QString open(const QString& caption, const QString& filter);
    QString save(const QString& caption, const QString& filter);
    void replace(Ask ask) { ask_ = std::move(ask); }
    // Where the next dialog opens.
    QString folder() const;

private:
    QString ask(Mode mode, const QString& caption, const QString& filter);

    QWidget* parent_;
    std::function<QString()> sceneFolder_;
    Ask ask_;
    QString lastFolder_;
};

}  // namespace lucerna
