#include "render/annual/annual_checkpoint.h"

#include "core/scene/scene_io.h"

#include <cstring>

namespace lucerna {

namespace {

constexpr char kMagic[8] = {'L', 'U', 'C', 'A', 'N', 'N', '0', '1'};

struct Fnv {
    uint64_t h = 0xcbf29ce484222325ULL;
    void add(const void* data, size_t n) {
        const auto* b = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ULL;
    }
    template <class T>
    void add(const std::vector<T>& v) {
        const uint64_t n = v.size();
        add(&n, sizeof n);
        if (!v.empty()) add(v.data(), v.size() * sizeof(T));
    }
};

// A point's record: its index, then each vector's length and floats.
bool writeVector(std::FILE* f, const std::vector<float>& v) {
    const uint32_t n = uint32_t(v.size());
    return std::fwrite(&n, sizeof n, 1, f) == 1 && (v.empty() || std::fwrite(v.data(), sizeof(float), v.size(), f) == v.size());
}

bool readVector(std::FILE* f, std::vector<float>& v) {
    uint32_t n = 0;
    if (std::fread(&n, sizeof n, 1, f) != 1 || n > (1u << 26)) return false;
    v.resize(n);
    return n == 0 || std::fread(v.data(), sizeof(float), n, f) == n;
}

}  // namespace

uint64_t annualCheckpointKey(const Scene& scene, const std::vector<V3d>& points, const V3d& normal, double latitudeDeg,
                             const std::string& settingsText) {
    Fnv h;
    const std::string text = saveSceneToString(scene);
    h.add(text.data(), text.size());
    for (const Object& o : scene.objects)
        if (o.worldMesh) h.add(o.worldMesh->vertices), h.add(o.worldMesh->triangles);
    h.add(points);
    h.add(&normal, sizeof normal);
    h.add(&latitudeDeg, sizeof latitudeDeg);
    h.add(settingsText.data(), settingsText.size());
    return h.h;
}

AnnualCheckpoint::~AnnualCheckpoint() {
    if (file_) std::fclose(file_);
}

std::map<size_t, PointCoefficients> AnnualCheckpoint::open(bool resume) {
    std::map<size_t, PointCoefficients> done;
    long good = 0;  // the end of the last whole record
    if (resume)
        if (std::FILE* f = std::fopen(path_.c_str(), "rb")) {
            char magic[8];
            uint64_t key = 0;
            if (std::fread(magic, 1, 8, f) == 8 && std::memcmp(magic, kMagic, 8) == 0 && std::fread(&key, sizeof key, 1, f) == 1 &&
                key == key_) {
                good = std::ftell(f);
                uint64_t point = 0;
                PointCoefficients c;
                while (std::fread(&point, sizeof point, 1, f) == 1 && readVector(f, c.sky) && readVector(f, c.coarseSky) &&
                       readVector(f, c.sunIndirect) && readVector(f, c.sunIndirectBatches)) {
                    done[size_t(point)] = c;
                    good = std::ftell(f);
                }
            }
            std::fclose(f);
        }
    if (good > 0 && !done.empty()) {
        // Go on after the last whole record (a torn one is overwritten).
        file_ = std::fopen(path_.c_str(), "r+b");
        if (file_ && std::fseek(file_, good, SEEK_SET) != 0) std::fclose(file_), file_ = nullptr;
        return done;
    }
    done.clear();
    file_ = std::fopen(path_.c_str(), "wb");
    if (file_ && !(std::fwrite(kMagic, 1, 8, file_) == 8 && std::fwrite(&key_, sizeof key_, 1, file_) == 1 && std::fflush(file_) == 0)) {
        std::fclose(file_);
        file_ = nullptr;
    }
    return done;
}

void AnnualCheckpoint::append(size_t point, const PointCoefficients& c) {
    std::lock_guard lock(mutex_);
    if (!file_) return;
    const uint64_t index = point;
    const bool ok = std::fwrite(&index, sizeof index, 1, file_) == 1 && writeVector(file_, c.sky) && writeVector(file_, c.coarseSky) &&
                    writeVector(file_, c.sunIndirect) && writeVector(file_, c.sunIndirectBatches) && std::fflush(file_) == 0;
    if (!ok) std::fclose(file_), file_ = nullptr;
}

void AnnualCheckpoint::remove() {
    std::lock_guard lock(mutex_);
    if (file_) std::fclose(file_), file_ = nullptr;
    std::remove(path_.c_str());
}

}  // namespace lucerna
