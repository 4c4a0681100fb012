#pragma once
// File > Import Model: a model file (OBJ with its MTL, glTF, GLB, FBX, COLLADA, ...) read by
// core/mesh/model_import.h into the document as one undo step, and the window that shows what was
// mapped and what was approximated.

#include "ui/document/document.h"

#include <QDialog>
#include <QStringList>

class QPlainTextEdit;

namespace lucerna {

struct PreparedImport {
    std::vector<Material> materials;
    std::vector<Object> objects;  // with their resolved world meshes
    std::vector<Light> lights;
    QStringList report;
};

// The model at `path` for doc's scene: coordinates in the scene's unit, names free in the scene,
// world meshes resolved. Throws std::runtime_error with one line when the file cannot be used.
PreparedImport prepareModelImport(const Document& doc, const QString& path);

// Reads the model and adds it to the document as one undo step; returns the report. Into a scene
// without geometry (a new document) the same step also places the camera in the model's largest
// room at eye height (render/trace/room_camera.h), when it has one, and the report says so. Throws
// std::runtime_error with one line (the document unchanged) when the file cannot be used.
QStringList importModelInto(Document* doc, const QString& path);

// A non-modal window with the report's lines (objectName "importReportDialog"; the text is the
// QPlainTextEdit "importReportText"), one per parent, reused by the next import.
class ImportReportDialog : public QDialog {
    Q_OBJECT
public:
    explicit ImportReportDialog(QWidget* parent);
    void setReport(const QString& file, const QStringList& lines);

    // The parent's report window (made on first use), filled and shown.
    static ImportReportDialog* present(QWidget* parent, const QString& file, const QStringList& lines);

private:
    QPlainTextEdit* text_;
};

}  // namespace lucerna
