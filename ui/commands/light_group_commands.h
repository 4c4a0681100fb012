#pragma once
// Undo commands on many lights at once (issue 19): an edit of a group or of a multi-selection of
// lights, and a change of the list of lights (a field of luminaires added, a group deleted). Each
// is one undo step however many lights it touches, and applies as one copy of the scene.

#include "ui/commands/change_value.h"

#include <vector>

namespace lucerna {

// EditLightsCommand(doc, indices, after, mergeKey, text): the lights at `indices` become `after`
// (one light per index). mergeKey 0: never merges; otherwise merges into the previous edit of the
// same lights with the same key (a field's arrow steps).
using EditLightsCommand = ChangeValue<ValueKind::Lights, &Document::lightsAt, &Document::setLights>;

// The scene's list of lights replaced by `after` (kept whole before and after: a field of 10,000
// luminaires is a few megabytes). Never merges.
class ReplaceLightsCommand : public ChangeValue<ValueKind::LightList, &Document::lights, &Document::replaceLights> {
public:
    ReplaceLightsCommand(Document* doc, std::vector<Light> after, const QString& text)
        : ChangeValue(doc, std::move(after), 0, text) {}
};

// The indices of the lights in `group`, in file order.
std::vector<int> groupMembers(const Scene& scene, const std::string& group);

}  // namespace lucerna
