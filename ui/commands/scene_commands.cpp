#include "ui/commands/scene_commands.h"

namespace lucerna {

EditCameraCommand::EditCameraCommand(Document* doc, const Camera& after, int mergeKey, const QString& text)
    : QUndoCommand(text), doc_(doc), before_(doc->scene().camera), after_(after), mergeKey_(mergeKey) {}
void EditCameraCommand::redo() { doc_->setCamera(after_); }
void EditCameraCommand::undo() { doc_->setCamera(before_); }
bool EditCameraCommand::mergeWith(const QUndoCommand* other) {
    const auto* o = static_cast<const EditCameraCommand*>(other);
    if (mergeKey_ == 0 || o->mergeKey_ != mergeKey_) return false;
    after_ = o->after_;
    return true;
}

}  // namespace lucerna
