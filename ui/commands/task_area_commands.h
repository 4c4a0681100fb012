#pragma once
// Undo commands on task areas (README, "Task areas"): edit one (any of its fields; a field's
// arrow steps merge into one undo step), add one (drawn in the plan or given in the dialog) and
// delete one.

#include "ui/commands/change_value.h"

#include <QUndoCommand>

namespace lucerna {

// EditTaskAreaCommand(doc, index, after, mergeKey, text). mergeKey 0: never merges.
using EditTaskAreaCommand = ChangeValue<ValueKind::TaskArea, &Document::taskArea, &Document::setTaskArea>;

// Adds a task area at `index` (at most the count) or deletes the one there; each the other's undo.
class TaskAreaListCommand : public QUndoCommand {
public:
    // "Add NAME".
    static TaskAreaListCommand* add(Document* doc, int index, TaskArea area);
    // "Delete NAME".
    static TaskAreaListCommand* remove(Document* doc, int index);

    void redo() override;
    void undo() override;

private:
    TaskAreaListCommand(Document* doc, int index, TaskArea area, bool adds, const QString& text);

    Document* doc_;
    int index_;
    TaskArea area_;
    bool adds_;
};

}  // namespace lucerna
