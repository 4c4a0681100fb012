#pragma once
// Files that are read whole (scenes, meshes, luminaire files, EXR images) must be regular files:
// a FIFO blocks the reader forever and a device such as /dev/zero never ends, so either is
// refused by name before it is opened.

#include <string>

namespace lucerna {

// What the path is when it exists and is not a regular file (after following links): "a
// directory", "a FIFO", "a character device", ...; empty for a regular file and for a path that
// does not exist or cannot be looked at (the caller's own open then reports that).
std::string nonRegularFileKind(const std::string& path);

}  // namespace lucerna
