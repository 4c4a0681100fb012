#include "ui/io/model_import_action.h"

#include "core/mesh/model_import.h"
#include "core/scene/scene_geometry.h"
#include "ui/commands/import_commands.h"
#include "ui/commands/scene_commands.h"
#include "ui/viewport/camera_navigation.h"
#include "render/trace/room_camera.h"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QPlainTextEdit>
#include <QVBoxLayout>

namespace lucerna {

PreparedImport prepareModelImport(const Document& doc, const QString& path) {
    const Scene& scene = doc.scene();
    ImportOptions options;
    options.sceneMetersPerUnit = scene.metersPerUnit;
    options.into = &scene;
    ModelImport model = importModel(QFileInfo(path).absoluteFilePath().toStdString(), options);

    PreparedImport out;
    // World meshes as the loader would resolve them (degenerate triangles dropped), in the
    // scene as it will be: the objects refer to the new materials.
    Scene withMaterials = scene;
    withMaterials.materials.insert(withMaterials.materials.end(), model.materials.begin(), model.materials.end());
    for (Object& o : model.objects) out.objects.push_back(resolvedObject(withMaterials, std::move(o)));
    out.materials = std::move(model.materials);
    out.lights = std::move(model.lights);
    for (const std::string& line : model.report) out.report << QString::fromStdString(line);
    return out;
}

QStringList importModelInto(Document* doc, const QString& path) {
    PreparedImport prepared = prepareModelImport(*doc, path);
    const QString text = QObject::tr("Import %1").arg(QFileInfo(path).fileName());
    bool hadGeometry = false;
    for (const Object& o : doc->scene().objects) hadGeometry |= o.worldMesh && !o.worldMesh->triangles.empty();
    QUndoStack* undo = doc->undoStack();
    undo->beginMacro(text);
    undo->push(new ImportModelCommand(doc, std::move(prepared.materials), std::move(prepared.objects),
                                      std::move(prepared.lights), text));
    if (!hadGeometry) {
        // A camera outside the walls would see a black first image.
        if (const auto camera = cameraInLargestRoom(doc->scene(), doc->scene().camera)) {
            undo->push(new EditCameraCommand(doc, *camera, 0, QObject::tr("Camera in the largest room")));
            prepared.report << QObject::tr("camera placed in the largest room at eye height, at (%1, %2, %3)")
                                   .arg(camera->position.x, 0, 'g', 5)
                                   .arg(camera->position.y, 0, 'g', 5)
                                   .arg(camera->position.z, 0, 'g', 5);
        } else {
            const SceneBounds b = sceneBounds(doc->scene());
            undo->push(new EditCameraCommand(doc, framedCamera(doc->scene().camera, b.lo, b.hi), 0,
                                             QObject::tr("Camera on the whole model")));
            prepared.report << QObject::tr("no enclosed room found: the camera frames the whole model");
        }
    }
    undo->endMacro();
    return prepared.report;
}

ImportReportDialog::ImportReportDialog(QWidget* parent) : QDialog(parent), text_(new QPlainTextEdit(this)) {
    setObjectName("importReportDialog");
    setModal(false);
    text_->setObjectName("importReportText");
    text_->setReadOnly(true);
    text_->setLineWrapMode(QPlainTextEdit::NoWrap);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::hide);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(text_);
    layout->addWidget(buttons);
    resize(960, 360);
}

void ImportReportDialog::setReport(const QString& file, const QStringList& lines) {
    setWindowTitle(tr("Import report: %1").arg(QFileInfo(file).fileName()));
    text_->setPlainText(lines.join('\n'));
}


ImportReportDialog* ImportReportDialog::present(QWidget* parent, const QString& file, const QStringList& lines) {
    auto* dialog = parent->findChild<ImportReportDialog*>(QString(), Qt::FindDirectChildrenOnly);
    if (!dialog) dialog = new ImportReportDialog(parent);
    dialog->setReport(file, lines);
    dialog->show();
    dialog->raise();
    return dialog;
}

}  // namespace lucerna
