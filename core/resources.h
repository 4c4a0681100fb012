#pragma once
// Where the bundled scenes and shaders are at run time: $LUCERNA_RESOURCE_DIR when set, else
// <prefix>/share/lucerna next to an installed executable (<prefix>/bin/lucerna), else the source
// tree the program was built from (LUCERNA_RESOURCE_DIR compiled in), so that both a build tree
// and an installed package find them.

#include <string>

namespace lucerna {

// The resource folder (holding scenes/ and shaders/), without a trailing slash.
std::string resourceDirectory();

// A folder of the user's cache ($XDG_CACHE_HOME/lucerna/NAME, else ~/.cache/lucerna/NAME), made
// if missing; empty when it cannot be made (callers then keep nothing).
std::string cacheDirectory(const std::string& name);

}  // namespace lucerna
