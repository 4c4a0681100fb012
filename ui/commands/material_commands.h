#pragma once
// Undo commands on materials: an edit of one material (type, colours, roughness, index of
// refraction, radiance). Consecutive edits of one material with the same merge key (one per
// slider drag or per field) fold into one undo step, as light edits do.

#include "ui/commands/change_value.h"

namespace lucerna {

// EditMaterialCommand(doc, index, after, mergeKey, text); mergeKey 0: never merges.
using EditMaterialCommand = ChangeValue<ValueKind::Material, &Document::material, &Document::setMaterial>;

// `m` turned into a material of `type`: the new type's fields carried over from what it had
// (a diffuse albedo becomes a mirror's reflectance, and back), the fields the type does not use
// reset to their defaults, so that the scene file says everything the document holds.
Material withMaterialType(const Material& m, MaterialType type);

QString materialTypeName(MaterialType type);

}  // namespace lucerna
