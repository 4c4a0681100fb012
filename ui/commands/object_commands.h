#pragma once
// Undo commands on objects: edit (name, material, transform), add (mesh import, with a material
// of its own when given) and delete. Consecutive edits of one object with the same merge key (one
// per drag or per field) fold into one undo step.

#include "ui/commands/add_or_delete.h"
#include "ui/commands/change_value.h"

#include <QUndoCommand>

#include <optional>

namespace lucerna {

// EditObjectCommand(doc, index, after, mergeKey, text) replaces an object (transform, material,
// name); `after` must carry its resolved world mesh. mergeKey 0: never merges.
using EditObjectCommand = ChangeValue<ValueKind::Object, &Document::object, &Document::setObject>;

// Adds an object at the end (mesh import), and a material for it at the end when `material` is
// given. The object must carry its resolved world mesh.
class AddObjectCommand : public QUndoCommand {
public:
    AddObjectCommand(Document* doc, Object object, std::optional<Material> material, const QString& text);
    void redo() override;
    void undo() override;

private:
    Document* doc_;
    Object object_;
    std::optional<Material> material_;
    int objectIndex_ = 0, materialIndex_ = 0;
};

// DeleteObjectCommand(doc, index): "Delete NAME".
using DeleteObjectCommand = AddOrDelete<&Document::object, &Document::insertObject, &Document::removeObject>;

}  // namespace lucerna
