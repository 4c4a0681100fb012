#pragma once
// Undo commands on materials: an edit of one material (type, colours, roughness, index of
// refraction, radiance). Consecutive edits of one material with the same merge key (one per
// slider drag or per field) fold into one undo step, as light edits do.

#include "ui/document/document.h"

#include <QUndoCommand>

namespace lucerna {

class EditMaterialCommand : public QUndoCommand {
public:
    // mergeKey 0: never merges.
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

// `m` turned into a material of `type`: the new type's fields carried over from what it had
// (a diffuse albedo becomes a mirror's reflectance, and back), the fields the type does not use
// reset to their defaults, so that the scene file says everything the document holds.
Material withMaterialType(const Material& m, MaterialType type);

QString materialTypeName(MaterialType type);

}  // namespace lucerna
