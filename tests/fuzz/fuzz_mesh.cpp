// libFuzzer: readMeshFile on any bytes, as a PLY, OFF, OBJ or STL file (the first byte picks the
// extension), either returns a mesh whose triangles index its vertices or throws
// std::runtime_error with one line; memory and time grow with the file, never with its claims
// (run with -rss_limit_mb and -timeout to see that).

#include "core/mesh/mesh_file.h"
#include "fuzz_input_file.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    static const char* const kExtensions[] = {"ply", "off", "obj", "stl"};
    const std::string path = lucerna::fuzz::inputFile(data + 1, size - 1, kExtensions[data[0] % 4]);
    try {
        const lucerna::TriangleMesh mesh = lucerna::readMeshFile(path);
        const int n = int(mesh.vertices.size());
        for (const lucerna::V3i& t : mesh.triangles)
            for (int k = 0; k < 3; ++k)
                if (t[k] < 0 || t[k] >= n) std::abort();
        for (const lucerna::V3d& v : mesh.vertices)
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) std::abort();
    } catch (const std::runtime_error& e) {
        if (std::string(e.what()).find('\n') != std::string::npos) std::abort();
    }
    return 0;
}
