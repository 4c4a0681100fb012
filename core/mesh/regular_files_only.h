#pragma once
// Assimp's importers open the files a model names (an OBJ's material libraries, a glTF's buffers,
// a COLLADA or X3D file's includes) through the importer's IO system. Assimp's default one calls
// fopen, which blocks forever on a FIFO, and reads a device such as /dev/zero without end. This
// one refuses every path that exists and is not a regular file, and remembers the first refusal so
// that the import fails with that reason in one line instead of hanging.

#include <assimp/DefaultIOSystem.h>

#include <string>

namespace lucerna {

class RegularFilesOnly : public Assimp::DefaultIOSystem {
public:
    // False for a path that is not a regular file (without opening it), else Assimp's answer.
    bool Exists(const char* path) const override;
    // Null for a path that is not a regular file, else Assimp's own stream.
    Assimp::IOStream* Open(const char* path, const char* mode = "rb") override;

    // "the file names fifo.mtl, which is a FIFO, not a regular file" for the first path refused;
    // empty while none was.
    const std::string& refusal() const { return refusal_; }

private:
    bool refuse(const char* path) const;
    mutable std::string refusal_;  // Exists is const in Assimp's interface
};

}  // namespace lucerna
