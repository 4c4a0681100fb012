#pragma once
// Files written whole or not at all (SPEC.md section 2): write to a temporary name in the same
// folder, then rename over the target. A crash or a cancelled render leaves no truncated file.

#include <functional>
#include <string>

namespace lucerna {

// Calls write(tempPath) to produce the file, then renames tempPath to path. If write throws, or
// the rename fails, the temporary is removed and the exception propagates (std::runtime_error
// with a one-line reason); `path` is untouched.
void writeAtomically(const std::string& path, const std::function<void(const std::string& tempPath)>& write);

// `text` as the whole content of the file at `path`, written as writeAtomically does; throws
// std::runtime_error ("PATH: cannot write") on failure.
void writeTextAtomically(const std::string& path, const std::string& text);

}  // namespace lucerna
