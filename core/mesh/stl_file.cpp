#include "core/mesh/stl_file.h"

#include "core/mesh/mesh_file_formats.h"
#include "core/mesh/text_words.h"
#include "core/message_text.h"

#include <array>
#include <bit>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <strings.h>

namespace lucerna {

namespace {

using Position = std::array<float, 3>;

// OpenMesh's order of STL positions (CmpVec in its STLReader.cc): lexicographic, coordinates
// within FLT_MIN of each other counting as equal. Kept as it was, so that the same positions
// merge into the same vertices.
struct ByPosition {
    bool operator()(const Position& a, const Position& b) const {
        if (std::fabs(a[0] - b[0]) <= FLT_MIN) {
            if (std::fabs(a[1] - b[1]) <= FLT_MIN) return a[2] < b[2] - FLT_MIN;
            return a[1] < b[1] - FLT_MIN;
        }
        return a[0] < b[0] - FLT_MIN;
    }
};

// The mesh as the triangles arrive: each new position a vertex, repeated positions shared.
class Triangles {
public:
    void add(const Position (&corners)[3]) {
        int v[3];
        for (int k = 0; k < 3; ++k) {
            const auto it = vertex_.find(corners[k]);
            if (it != vertex_.end()) {
                v[k] = it->second;
                continue;
            }
            if (mesh.vertices.size() >= size_t(INT_MAX)) throw std::runtime_error("more vertices than a mesh can index");
            v[k] = int(mesh.vertices.size());
            mesh.vertices.emplace_back(corners[k][0], corners[k][1], corners[k][2]);
            vertex_[corners[k]] = v[k];
        }
        if (v[0] != v[1] && v[0] != v[2] && v[1] != v[2]) mesh.triangles.emplace_back(v[0], v[1], v[2]);
    }
    TriangleMesh mesh;

private:
    std::map<Position, int, ByPosition> vertex_;
};

// A word of the file in quotes, for messages.
std::string quoted(std::string_view word) {
    std::string q(1, '"');
    q += printableWord(word);
    q += '"';
    return q;
}

TriangleMesh readBinary(const std::string& bytes, size_t count) {
    static_assert(std::endian::native == std::endian::little, "binary STL values are read in host order");
    Triangles triangles;
    for (size_t t = 0; t < count; ++t) {
        const char* record = bytes.data() + 84 + 50 * t;
        Position corners[3];
        std::memcpy(corners, record + 12, sizeof corners);  // after the normal
        for (const Position& p : corners)
            if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])))
                throw std::runtime_error("triangle " + std::to_string(t) + " has a corner that is not a finite point");
        triangles.add(corners);
    }
    return std::move(triangles.mesh);
}

TriangleMesh readAscii(const std::string& bytes) {
    TextWords words(bytes, 0, false);
    const auto refuse = [&](const std::string& why) {
        throw std::runtime_error("line " + std::to_string(words.line()) + ": " + why);
    };
    const auto is = [](std::string_view word, const char* keyword) {
        return word.size() == std::strlen(keyword) && strncasecmp(word.data(), keyword, word.size()) == 0;
    };
    // The next word, which must be `keyword`.
    const auto expect = [&](const char* keyword) {
        const std::optional<std::string_view> w = words.next();
        if (!w) throw std::runtime_error(std::string("the file ends inside a facet, before \"") + keyword + "\" (it is cut short)");
        if (!is(*w, keyword)) refuse(quoted(*w) + " where the facet needs " + quoted(keyword));
    };
    const std::optional<std::string_view> first = words.next();
    if (!first || !is(*first, "solid"))
        throw std::runtime_error("not an STL file: neither binary (84 bytes and 50 for each triangle its header counts) "
                                 "nor ASCII (starting with \"solid\")");
    words.skipLine();  // the solid's name
    Triangles triangles;
    for (std::optional<std::string_view> w = words.next(); w; w = words.next()) {
        if (is(*w, "endsolid") || is(*w, "solid")) {
            words.skipLine();  // its name
            continue;
        }
        if (!is(*w, "facet")) refuse(quoted(*w) + " where a facet (or endsolid) should start");
        expect("normal");
        for (int k = 0; k < 3; ++k)  // read but not used (exporters write nan for degenerate facets)
            if (!words.next()) throw std::runtime_error("the file ends inside a facet's normal (it is cut short)");
        expect("outer");
        expect("loop");
        Position corners[3];
        for (Position& p : corners) {
            expect("vertex");
            for (float& c : p) {
                const std::optional<std::string_view> value = words.next();
                if (!value) throw std::runtime_error("the file ends inside a vertex (it is cut short)");
                std::string problem;
                const std::optional<float> f = parseCoordinate(*value, &problem);
                if (!f) refuse("vertex coordinate " + problem);
                c = *f;
            }
        }
        expect("endloop");
        expect("endfacet");
        triangles.add(corners);
    }
    return std::move(triangles.mesh);
}

}  // namespace

TriangleMesh readStlBytes(const std::string& bytes) {
    // OpenMesh's test: binary exactly when the size matches the triangle count in the header.
    if (bytes.size() >= 84) {
        uint32_t count = 0;
        std::memcpy(&count, bytes.data() + 80, 4);
        if (84 + 50 * uint64_t(count) == bytes.size()) return readBinary(bytes, count);
    }
    return readAscii(bytes);
}

}  // namespace lucerna
