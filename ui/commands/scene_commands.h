#pragma once
// Undo commands on materials, objects and the camera. Edits with the same merge key (one per
// drag, slider or field) fold into one undo step, as light edits do.

#include "core/document.h"

#include <QUndoCommand>

namespace lucerna {

class EditMaterialCommand : public QUndoCommand {
public:
    EditMaterialCommand(Document* doc, int index, Material after, int mergeKey, const QString& text);
    void redo() override;
    void undo() override;
    int id() const override { return 1002; }
    bool mergeWith(const QUndoCommand* other) override;

private:
    Document* doc_;
    int index_;
    Material before_, after_;
    int mergeKey_;
};

// Replaces an object (transform, material, name); `after` must carry its resolved world mesh.
class EditObjectCommand : public QUndoCommand {
public:
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

// Adds an object (mesh import), and a material for it when `material` is given.
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
