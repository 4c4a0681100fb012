#pragma once
// Undo commands on objects: edit (name, material, transform), add (mesh import, with a material
// of its own when given) and delete. Consecutive edits of one object with the same merge key (one
// per drag or per field) fold into one undo step.

#include "ui/document/document.h"

#include <QUndoCommand>

#include <optional>

namespace lucerna {

// Replaces an object (transform, material, name); `after` must carry its resolved world mesh.
class EditObjectCommand : public QUndoCommand {
public:
    // mergeKey 0: never merges.
    EditObjectCommand(Document* doc, int index, Object after, int mergeKey, const QString& text);
    void redo() override;
    void undo() override;
    int id() const override { return 1003; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* doc_;
    int index_;
    Object before_, after_;
    int mergeKey_;
};

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

class DeleteObjectCommand : public QUndoCommand {
public:
    DeleteObjectCommand(Document* doc, int index);
    void redo() override;
    void undo() override;

private:
    Document* doc_;
    int index_;
    Object object_;
};

}  // namespace lucerna
