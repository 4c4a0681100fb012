#include "ui/commands/object_commands.h"

#include <QObject>

namespace lucerna {

EditObjectCommand::EditObjectCommand(Document* doc, int index, Object after, int mergeKey, const QString& text)
    : QUndoCommand(text), doc_(doc), index_(index), before_(doc->scene().objects.at(size_t(index))),
      after_(std::move(after)), mergeKey_(mergeKey) {}

void EditObjectCommand::redo() { doc_->setObject(index_, after_); }
void EditObjectCommand::undo() { doc_->setObject(index_, before_); }

bool EditObjectCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const EditObjectCommand*>(other);
    if (mergeKey_ == 0 || o->mergeKey_ != mergeKey_ || o->index_ != index_) return false;
    after_ = o->after_;
    return true;
}

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

DeleteObjectCommand::DeleteObjectCommand(Document* doc, int index)
    : QUndoCommand(QObject::tr("Delete %1").arg(QString::fromStdString(doc->scene().objects.at(size_t(index)).name))),
      doc_(doc), index_(index), object_(doc->scene().objects.at(size_t(index))) {}

void DeleteObjectCommand::redo() { doc_->removeObject(index_); }
void DeleteObjectCommand::undo() { doc_->insertObject(index_, object_); }

}  // namespace lucerna
