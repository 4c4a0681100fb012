#include "ui/commands/room_commands.h"

namespace lucerna {

RoomEditCommand::RoomEditCommand(Document* doc, RoomEdit edit, const QString& text)
    : QUndoCommand(text), doc_(doc), edit_(std::move(edit)) {}

// One published scene per step, whatever the edit takes out and puts in. The document has no
// setter for rooms, so the structure signal its per-item setters send is sent here (the
// outliner lists rooms, their surfaces and openings).
void RoomEditCommand::redo() {
    doc_->modify([this](Scene& s) { applyRoomEdit(s, edit_); });
    emit doc_->structureChanged();
}

void RoomEditCommand::undo() {
    doc_->modify([this](Scene& s) { revertRoomEdit(s, edit_); });
    emit doc_->structureChanged();
}

}  // namespace lucerna
