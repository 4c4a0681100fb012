#pragma once
// What the scene reader shares with its second half, the resolution of meshes and luminaire
// files (scene_resolve.cpp): the JSON paths and quoting of its one-line messages, and the step
// itself. Internal to core/.

#include "core/scene/json_string.h"
#include "core/scene/scene_io.h"

#include <string>

namespace lucerna {

// A string from the file, quoted as JSON would, so that a message stays on one line whatever
// the file holds.
inline std::string quote(const std::string& s) { return jsonQuoted(s, JsonEscapes::OneLine); }
// objects[2]: the JSON path of an array's item.
inline std::string item(const std::string& parent, size_t i) { return parent + "[" + std::to_string(i) + "]"; }

// Reads the scene's mesh and luminaire files (relative to scene.baseDir, each once) and sets
// every object's world mesh and every luminaire's distribution; `label` starts each message.
// Throws SceneError with one line, leaving the scene unchanged.
void resolveScene(Scene& scene, LoadReport* report, const std::string& label);

}  // namespace lucerna
