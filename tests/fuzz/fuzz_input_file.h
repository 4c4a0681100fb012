#pragma once
// The readers of mesh and EXR files take a path, so each fuzz input is written to a file of this
// process's own (under TMPDIR) with the extension the reader dispatches on.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace lucerna::fuzz {

inline std::string inputFile(const uint8_t* data, size_t size, const std::string& extension) {
    const char* tmp = std::getenv("TMPDIR");
    const std::string path = std::string(tmp && *tmp ? tmp : "/tmp") + "/lucerna-fuzz-" + std::to_string(::getpid()) + "." + extension;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) std::abort();
    if (size && std::fwrite(data, 1, size, f) != size) std::abort();
    std::fclose(f);
    return path;
}

}  // namespace lucerna::fuzz
