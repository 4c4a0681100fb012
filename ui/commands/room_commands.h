#pragma once
// The undo command of every edit of the rooms (README, "Rooms"): a room added, drawn or edited,
// an opening added, edited or removed, objects marked as a room, a room removed. Each is one
// undo step, computed once (core/scene/room_edit.h) and applied or reverted exactly.

#include "core/scene/room_edit.h"
#include "ui/document/document.h"

#include <QUndoCommand>

namespace lucerna {

class RoomEditCommand : public QUndoCommand {
public:
    // `edit` must have been computed against the document's scene as it is when pushed.
    RoomEditCommand(Document* doc, RoomEdit edit, const QString& text);
    void redo() override;
    void undo() override;

private:
    Document* doc_;
    RoomEdit edit_;
};

}  // namespace lucerna
