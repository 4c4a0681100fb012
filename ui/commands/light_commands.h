#pragma once
// Undo commands on the scene's lights: add (also duplicate and place-by-click), delete, and edit
// (move, aim, rename, colour, power, cone). Consecutive edits of one light with the same merge
// key fold into one command, so a gizmo drag or a slider drag is a single undo step.

#include "ui/commands/add_or_delete.h"
#include "ui/commands/change_value.h"

namespace lucerna {

// Add (an index and a light) and delete (an index: "Delete NAME") are one command class.
using AddLightCommand = AddOrDelete<&Document::light, &Document::insertLight, &Document::removeLight>;
using DeleteLightCommand = AddLightCommand;

// EditLightCommand(doc, index, after, mergeKey, text): merges into the previous edit of the same
// light with the same key (one key per drag or per field); mergeKey 0: never merges.
using EditLightCommand = ChangeValue<ValueKind::Light, &Document::light, &Document::setLight>;

// A new light of a type (SPEC.md types) above the middle of the scene: a point or spot light of
// 1000 lm at 3000 K, a sun of 2 W/m² (about 1370 lx).
Light defaultLight(const Scene& scene, LightType type, const std::string& name);
QString lightTypeName(LightType type);

}  // namespace lucerna
