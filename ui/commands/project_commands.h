#pragma once
// The undo command of File > Project Settings: the project's details, the scene's maintenance
// factor, its EN 12464-1 edition and its lighting energy's settings (ProjectSettings,
// ui/document/document.h) replaced together,
// so that the dialog's OK is one undo step however many of its fields changed.

#include "ui/commands/change_value.h"

namespace lucerna {

// EditProjectSettingsCommand(doc, after, mergeKey, text); mergeKey 0: never merges (the dialog's
// OK is a step of its own).
using EditProjectSettingsCommand =
    ChangeValue<ValueKind::Project, &Document::projectSettings, &Document::setProjectSettings>;

}  // namespace lucerna
