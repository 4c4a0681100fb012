#pragma once
// Undo command for File > Import Model: the materials, objects and lights of one model added
// together, one undo step.

#include "ui/document/document.h"

#include <QUndoCommand>

#include <vector>

namespace lucerna {

// Appends the materials, objects and lights (in that order: objects refer to the materials).
// Objects must carry their resolved world meshes; names must be free in the document's scene.
class ImportModelCommand : public QUndoCommand {
public:
    ImportModelCommand(Document* doc, std::vector<Material> materials, std::vector<Object> objects,
                       std::vector<Light> lights, const QString& text);
    void redo() override;
    void undo() override;

private:
    Document* doc_;
    std::vector<Material> materials_;
    std::vector<Object> objects_;
    std::vector<Light> lights_;
    size_t materialsBefore_, objectsBefore_, lightsBefore_;
};

}  // namespace lucerna
