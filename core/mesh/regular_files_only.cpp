#include "core/mesh/regular_files_only.h"

#include "core/message_text.h"
#include "core/regular_file.h"

#include <filesystem>

namespace lucerna {

bool RegularFilesOnly::refuse(const char* path) const {
    const std::string kind = path ? nonRegularFileKind(path) : std::string();
    if (kind.empty()) return false;
    if (refusal_.empty())
        refusal_ = "the file names " + printableWord(std::filesystem::path(path).filename().string()) + ", which is " +
                   kind + ", not a regular file";
    return true;
}

bool RegularFilesOnly::Exists(const char* path) const {
    return !refuse(path) && DefaultIOSystem::Exists(path);
}

Assimp::IOStream* RegularFilesOnly::Open(const char* path, const char* mode) {
    return refuse(path) ? nullptr : DefaultIOSystem::Open(path, mode);
}

}  // namespace lucerna
