#pragma once
// File > Import Mesh and Import Model: a mesh file as a new object with a material of its own,
// or a model (OBJ+MTL, glTF, FBX, COLLADA, ...: objects, materials, lights) into the open scene or
// a new one; each import is one undo step.

#include <QObject>
#include <QString>

#include <functional>

class QMenu;

namespace lucerna {

class CameraPanel;
class Document;
class FileActions;
class FileDialogs;
class Outliner;
class WindowMessages;

// Where File > Import Model puts the model, as the user answered.
enum class ImportTarget { OpenScene, NewScene, Cancel };

class ImportActions : public QObject {
    Q_OBJECT
public:
    // `files` replaces the scene for an import into a new one and asks before unsaved changes
    // are lost; `outliner` selects what a mesh import added; `camera` learns the camera an import
    // placed, as the one Reset Camera returns to.
    ImportActions(Document& doc, FileActions& files, Outliner& outliner, CameraPanel& camera, FileDialogs& dialogs,
                  WindowMessages& messages);

    // Adds Import Mesh and Import Model to `menu`.
    void addTo(QMenu* menu);

    // The operations behind the menu, without dialogs. Each returns false and says why
    // (WindowMessages::fail) when it fails. Each first autosaves unsaved changes
    // (FileActions::secureUnsavedWork): an importer that crashes loses no work.
    // Adds the mesh file as a new object with a material of its own, and selects it.
    bool importMeshFile(const QString& path);
    // Adds a model in one undo step and shows the import report (ui/io/model_import_action.h) in
    // a non-modal window: into a new scene (untitled, the model on a floor, the camera framing
    // it) or the open one.
    bool importModelFile(const QString& path, ImportTarget target = ImportTarget::OpenScene);
    // Replaces the question File > Import Model asks (new scene or this one).
    void setImportQuestion(std::function<ImportTarget()> ask) { askTarget_ = std::move(ask); }

private:
    ImportTarget askTarget();

    Document& doc_;
    FileActions& files_;
    Outliner& outliner_;
    CameraPanel& camera_;
    FileDialogs& dialogs_;
    WindowMessages& messages_;
    std::function<ImportTarget()> askTarget_;
};

}  // namespace lucerna
