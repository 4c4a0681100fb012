#pragma once
// Undo commands on the camera. (Material and object commands have files of their own, included
// here for the callers that used to find them in this one.)

#include "ui/commands/material_commands.h"
#include "ui/commands/object_commands.h"
#include "ui/document/document.h"

#include <QUndoCommand>

namespace lucerna {

// Edits with the same merge key (one per drag or per run of wheel steps) fold into one undo step.
class EditCameraCommand : public QUndoCommand {
public:
    EditCameraCommand(Document* doc, const Camera& after, int mergeKey, const QString& text);
    void redo() override;
    void undo() override;
    int id() const override { return 1004; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* doc_;
    Camera before_, after_;
    int mergeKey_;
};

}  // namespace lucerna
