#pragma once
// The undo command of the lighting energy's settings (README, "Energy (LENI)"): one step per
// change of the building type or of one factor, made by the Energy page.

#include "ui/commands/change_value.h"

namespace lucerna {

// EditEnergyCommand(doc, after, mergeKey, text); after absent: the scene states no energy
// settings. mergeKey 0: never merges.
using EditEnergyCommand = ChangeValue<ValueKind::Energy, &Document::energy, &Document::setEnergy>;

}  // namespace lucerna
