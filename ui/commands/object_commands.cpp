#include "ui/commands/object_commands.h"

namespace lucerna {

AddObjectCommand::AddObjectCommand(Document* doc, Object object, std::optional<Material> material, const QString& text)
    : QUndoCommand(text), doc_(doc), object_(std::move(object)), material_(std::move(material)),
      objectIndex_(int(doc->scene().objects.size())), materialIndex_(int(doc->scene().materials.size())) {}

void AddObjectCommand::redo() {
    // The material first: the object refers to it.
    if (material_) doc_->insertMaterial(materialIndex_, *material_);
    doc_->insertObject(objectIndex_, object_);
}

void AddObjectCommand::undo() {
    doc_->removeObject(objectIndex_);
    if (material_) doc_->removeMaterial(materialIndex_);
}

}  // namespace lucerna
