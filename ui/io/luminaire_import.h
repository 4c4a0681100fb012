#pragma once
// Edit > Add Luminaire: a goniometric luminaire from a manufacturer's IES or EULUMDAT file.

#include "ui/document/document.h"

#include <QString>

namespace lucerna {

// A luminaire light for `file`, named after it (unique in the scene), hung where the Edit menu
// puts a new light (above the middle of the scene), nadir straight down, at the file's own flux;
// its path as the scene file stores paths (mesh_import.h, scenePathOf) and its distribution
// loaded. Throws std::runtime_error with a one-line reason when the file cannot be read.
Light luminaireFromFile(const Document& doc, const QString& file);

}  // namespace lucerna
