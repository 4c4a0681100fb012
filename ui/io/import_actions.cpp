#include "ui/io/import_actions.h"

#include "ui/commands/object_commands.h"
#include "ui/document/new_scene.h"
#include "ui/io/file_dialogs.h"
#include "ui/io/mesh_import.h"
#include "ui/io/model_import_action.h"
#include "core/read_crash_hook.h"
#include "ui/scene_panels/camera_panel.h"
#include "ui/scene_panels/outliner.h"
#include "ui/window/file_actions.h"
#include "ui/window/menu_entry.h"
#include "ui/window/window_messages.h"

#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>

namespace lucerna {

ImportActions::ImportActions(Document& doc, FileActions& files, Outliner& outliner, CameraPanel& camera,
                             FileDialogs& dialogs, WindowMessages& messages)
    : doc_(doc), files_(files), outliner_(outliner), camera_(camera), dialogs_(dialogs), messages_(messages) {}

void ImportActions::addTo(QMenu* menu) {
    addMenuEntry(menu, tr("&Import Mesh..."), "actionImportMesh", QKeySequence(tr("Ctrl+I")), this, [this] {
        const QString path = dialogs_.open(tr("Import a mesh"), tr("Meshes (*.obj *.ply *.off *.stl)"));
        if (!path.isEmpty()) messages_.warnUnless(importMeshFile(path), tr("Import mesh"));
    });
    addMenuEntry(menu, tr("Import &Model..."), "actionImportModel", QKeySequence(tr("Ctrl+Shift+I")), this, [this] {
        const QString path = dialogs_.open(
            tr("Import a model"), tr("Models (*.obj *.gltf *.glb *.fbx *.dae *.3ds *.ply *.stl *.blend);;All files (*)"));
        if (path.isEmpty()) return;
        const ImportTarget target = askTarget();
        if (target == ImportTarget::Cancel || (target == ImportTarget::NewScene && !files_.maybeSave())) return;
        messages_.warnUnless(importModelFile(path, target), tr("Import model"));
    });
}

ImportTarget ImportActions::askTarget() {
    if (askTarget_) return askTarget_();
    QMessageBox box(QMessageBox::Question, tr("Import model"), tr("Import the model into a new scene or into this one?"),
                    QMessageBox::Cancel, messages_.window());
    QPushButton* fresh = box.addButton(tr("New Scene"), QMessageBox::AcceptRole);
    QPushButton* here = box.addButton(tr("This Scene"), QMessageBox::AcceptRole);
    box.setDefaultButton(here);
    box.exec();
    return box.clickedButton() == fresh ? ImportTarget::NewScene
           : box.clickedButton() == here ? ImportTarget::OpenScene
                                         : ImportTarget::Cancel;
}

bool ImportActions::importMeshFile(const QString& path) {
    files_.secureUnsavedWork();
    MeshImport imported;
    const auto read = [&] {
        crashHereWhenTesting("import");
        imported = importMesh(doc_, path);
    };
    if (!messages_.attempt(read, tr("Could not import %1").arg(path))) return false;
    const QString text = tr("Import %1").arg(QString::fromStdString(imported.object.name));
    doc_.undoStack()->push(new AddObjectCommand(&doc_, std::move(imported.object), std::move(imported.material), text));
    outliner_.select(Outliner::Kind::Object, int(doc_.scene().objects.size()) - 1);
    messages_.show(tr("Imported %1").arg(path), 5000);
    return true;
}

bool ImportActions::importModelFile(const QString& path, ImportTarget target) {
    if (target == ImportTarget::Cancel) return false;
    files_.secureUnsavedWork();
    QStringList report;
    const auto importModel = [&] {
        crashHereWhenTesting("import");
        const Camera before = doc_.scene().camera;
        // A new scene is a new document, not an undo step of the old one.
        if (target == ImportTarget::NewScene) files_.replaceScene(newSceneWithModel(path, &report), {}, true);
        else report = importModelInto(&doc_, path);
        // A camera the import placed (in the largest room) is the one Reset Camera returns to.
        if (doc_.scene().camera != before) camera_.setHomeCamera(doc_.scene().camera);
    };
    if (!messages_.attempt(importModel, tr("Could not import %1").arg(path))) return false;
    messages_.show(report.value(0), 8000);
    ImportReportDialog::present(messages_.window(), path, report);
    return true;
}

}  // namespace lucerna
