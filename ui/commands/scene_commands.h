#pragma once
// Undo commands on the camera. (Material and object commands have files of their own, included
// here for the callers that used to find them in this one.)

#include "ui/commands/change_value.h"
#include "ui/commands/material_commands.h"
#include "ui/commands/object_commands.h"

namespace lucerna {

// EditCameraCommand(doc, after, mergeKey, text): edits with the same merge key (one per drag or
// per run of wheel steps) fold into one undo step; mergeKey 0: never merges.
using EditCameraCommand = ChangeValue<ValueKind::Camera, &Document::camera, &Document::setCamera>;

}  // namespace lucerna
