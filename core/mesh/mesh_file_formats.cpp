#include "core/mesh/mesh_file_formats.h"

#include "core/mesh/text_words.h"
#include "core/message_text.h"

#include <bit>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string_view>

namespace lucerna {

std::optional<float> parseCoordinate(std::string_view word, std::string* problem) {
    std::string_view digits = word;
    if (digits.starts_with('+')) digits.remove_prefix(1);  // istream accepts it, from_chars not
    const char* end = digits.data() + digits.size();
    float f = 0;
    auto r = std::from_chars(digits.data(), end, f);
    if (r.ec == std::errc() && r.ptr == end && std::isfinite(f)) return f;
    double d = 0;
    r = std::from_chars(digits.data(), end, d);
    const bool number = !digits.empty() && r.ptr == end && (r.ec == std::errc() || r.ec == std::errc::result_out_of_range);
    if (!number)
        *problem = '"' + printableWord(word).append("\" is not a number");
    else if (r.ec == std::errc() && !std::isfinite(d))
        *problem = printableWord(word) + " is not a finite number";
    else if (r.ec == std::errc() && std::abs(d) <= FLT_MAX)
        return float(d);  // below single precision's smallest normal: from_chars<float> says out of range
    else
        *problem = printableWord(word) + " lies beyond single-precision range";
    return std::nullopt;
}

std::optional<long long> parseInteger(std::string_view word) {
    if (word.starts_with('+')) word.remove_prefix(1);
    long long v = 0;
    const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
    if (r.ec != std::errc() || r.ptr != word.data() + word.size()) return std::nullopt;
    return v;
}

namespace {

[[noreturn]] void refuse(const std::string& why) { throw std::runtime_error(why); }

std::string formatValue(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// The triangles of the recorded polygons (fans from each first vertex), after every index has
// been checked against the vertices.
void addPolygon(TriangleMesh& mesh, const std::vector<long long>& polygon) {
    if (polygon.size() < 3) return;  // as OpenMesh's importer: no face from fewer than 3 vertices
    for (size_t k = 1; k + 1 < polygon.size(); ++k)
        mesh.triangles.emplace_back(int(polygon[0]), int(polygon[k]), int(polygon[k + 1]));
}

void checkIndices(const TriangleMesh& mesh) {
    const long long n = (long long)mesh.vertices.size();
    for (const V3i& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (t[k] < 0 || t[k] >= n) refuse("a face refers to a vertex that does not exist");
}

// ---- PLY ------------------------------------------------------------------------------------

enum class PlyType { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64, None };

PlyType plyType(const std::string& name) {
    if (name == "char" || name == "int8") return PlyType::Int8;
    if (name == "uchar" || name == "uint8") return PlyType::Uint8;
    if (name == "short" || name == "int16") return PlyType::Int16;
    if (name == "ushort" || name == "uint16") return PlyType::Uint16;
    if (name == "int" || name == "int32") return PlyType::Int32;
    if (name == "uint" || name == "uint32") return PlyType::Uint32;
    if (name == "float" || name == "float32") return PlyType::Float32;
    if (name == "double" || name == "float64") return PlyType::Float64;
    return PlyType::None;
}

size_t plySize(PlyType t) {
    switch (t) {
    case PlyType::Int8: case PlyType::Uint8: return 1;
    case PlyType::Int16: case PlyType::Uint16: return 2;
    case PlyType::Int32: case PlyType::Uint32: case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
    case PlyType::None: break;
    }
    return 0;
}

bool isFloat(PlyType t) { return t == PlyType::Float32 || t == PlyType::Float64; }

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::None;       // of the value, or of a list's items
    PlyType countType = PlyType::None;  // a list's count; None for a scalar
};

struct PlyElement {
    std::string name;
    unsigned long long count = 0;
    std::vector<PlyProperty> properties;
};

// Binary values, with every read checked against the end of the file.
class PlyBytes {
public:
    PlyBytes(std::string_view bytes, size_t from, bool bigEndian) : bytes_(bytes), at_(from), swap_(bigEndian) {}

    bool has(size_t n) const { return n <= bytes_.size() - at_; }
    void skip(size_t n) { at_ += n; }

    // A value as a double (integers exactly), or nothing when the file ends first.
    std::optional<double> value(PlyType t) {
        const size_t n = plySize(t);
        if (!has(n)) return std::nullopt;
        unsigned char b[8];
        std::memcpy(b, bytes_.data() + at_, n);
        at_ += n;
        if (swap_)
            for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
        switch (t) {
        case PlyType::Int8: return double(int8_t(b[0]));
        case PlyType::Uint8: return double(b[0]);
        case PlyType::Int16: return double(load<int16_t>(b));
        case PlyType::Uint16: return double(load<uint16_t>(b));
        case PlyType::Int32: return double(load<int32_t>(b));
        case PlyType::Uint32: return double(load<uint32_t>(b));
        case PlyType::Float32: return double(load<float>(b));
        case PlyType::Float64: return load<double>(b);
        case PlyType::None: break;
        }
        return std::nullopt;
    }

private:
    template <class T>
    static T load(const unsigned char* b) {
        T v;
        std::memcpy(&v, b, sizeof v);
        return v;
    }
    std::string_view bytes_;
    size_t at_;
    bool swap_;
};

}  // namespace

TriangleMesh readPlyBytes(const std::string& bytes) {
    static_assert(std::endian::native == std::endian::little, "binary PLY values are read in host order");
    // The header (its form already checked by readMeshFile): the format and the elements.
    const size_t endHeader = bytes.find("\nend_header");
    if (endHeader == std::string::npos) refuse("the PLY header has no end_header line");
    size_t body = bytes.find('\n', endHeader + 1);
    body = body == std::string::npos ? bytes.size() : body + 1;
    std::string format;
    std::vector<PlyElement> elements;
    {
        TextWords header(std::string_view(bytes).substr(0, endHeader + 1), 0, false);
        header.next();  // "ply"
        std::vector<std::string_view> line;
        long long current = header.line();
        const auto take = [&] {
            if (line.empty()) return;
            const auto word = [&](size_t i) { return i < line.size() ? std::string(line[i]) : std::string(); };
            if (line[0] == "format") {
                format = word(1);
            } else if (line[0] == "element") {
                PlyElement e;
                e.name = word(1);
                // Every record takes at least a byte (or a word): no count beyond the file's size.
                const std::optional<long long> count = parseInteger(line.size() > 2 ? line[2] : "");
                if (!count || *count < 0 || (unsigned long long)*count > bytes.size())
                    refuse("the PLY header's count of " + printableWord(e.name) + " is not a count the file can hold");
                e.count = (unsigned long long)*count;
                elements.push_back(e);
            } else if (line[0] == "property" && !elements.empty()) {
                PlyProperty p;
                if (word(1) == "list") {
                    p.countType = plyType(word(2));
                    p.type = plyType(word(3));
                    p.name = word(4);
                } else {
                    p.type = plyType(word(1));
                    p.name = word(2);
                }
                if (p.type == PlyType::None || (word(1) == "list" && p.countType == PlyType::None))
                    refuse("the PLY header has a property of an unknown type");
                elements.back().properties.push_back(p);
            }
            line.clear();
        };
        for (auto w = header.next(); w; w = header.next()) {
            if (header.line() != current) {
                take();
                current = header.line();
            }
            // comment and obj_info lines are free text
            if (!line.empty() && (line[0] == "comment" || line[0] == "obj_info")) continue;
            line.push_back(*w);
        }
        take();
    }
    const bool ascii = format == "ascii";
    if (!ascii && format != "binary_little_endian" && format != "binary_big_endian") refuse("unknown PLY format");

    TriangleMesh mesh;
    std::vector<long long> polygon;
    TextWords words(bytes, body, false);
    PlyBytes binary(bytes, body, format == "binary_big_endian");
    const auto cutShort = [&](const PlyElement& e, unsigned long long i) {
        refuse("the file ends inside " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count) +
               " (it is cut short, or a count in it is wrong)");
    };
    // One value: a number in ASCII (any word for values nobody reads, as OpenMesh), or the bytes
    // of its type. False when the file has ended.
    const auto readValue = [&](PlyType t, bool used, double* out, std::string* word) -> bool {
        if (!ascii) {
            const std::optional<double> v = binary.value(t);
            if (!v) return false;
            *out = *v;
            return true;
        }
        const std::optional<std::string_view> w = words.next();
        if (!w) return false;
        *word = std::string(*w);
        if (used) {
            if (isFloat(t)) {
                std::string problem;
                const std::optional<float> f = parseCoordinate(*w, &problem);
                if (!f) refuse("line " + std::to_string(words.line()) + ": " + problem);
                *out = *f;
            } else {
                const std::optional<long long> i = parseInteger(*w);
                if (!i) refuse("line " + std::to_string(words.line()) + ": \"" + printableWord(*w) + "\" is not an integer");
                *out = double(*i);
            }
        }
        return true;
    };
    const auto where = [&]() { return ascii ? "line " + std::to_string(words.line()) + ": " : std::string(); };

    for (const PlyElement& e : elements) {
        const bool isVertex = e.name == "vertex", isFace = e.name == "face";
        if (isVertex) mesh.vertices.reserve(size_t(std::min<unsigned long long>(e.count, bytes.size() / 3)));
        for (unsigned long long i = 0; i < e.count && !e.properties.empty(); ++i) {
            float xyz[3] = {0, 0, 0};
            for (const PlyProperty& p : e.properties) {
                double v = 0;
                std::string word;
                if (p.countType == PlyType::None) {
                    const int axis = !isVertex ? -1 : p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
                    if (!readValue(p.type, axis >= 0, &v, &word)) cutShort(e, i);
                    if (axis >= 0) {
                        if (!ascii && !(std::isfinite(v) && std::abs(v) <= FLT_MAX))
                            refuse("vertex " + std::to_string(i) + " has a coordinate that is not a finite number in single precision");
                        xyz[axis] = float(v);
                    }
                    continue;
                }
                // A list: its count, then that many items, each read before the next (so that a
                // count the file cannot hold ends in "cut short", not in a huge allocation).
                const bool indices = isFace && (p.name == "vertex_indices" || p.name == "vertex_index");
                if (indices && isFloat(p.type)) refuse("the face's vertex indices are not integers (" + p.name + ")");
                if (!readValue(p.countType, true, &v, &word)) cutShort(e, i);
                if (isFloat(p.countType) || v < 0 || v != std::floor(v))
                    refuse(where() + e.name + " " + std::to_string(i) + ": the list count of " + p.name + " is " +
                           (ascii ? printableWord(word) : formatValue(v)) + ", not a count");
                const auto count = (unsigned long long)v;
                if (!ascii && !binary.has(count * plySize(p.type)))  // binary: checked at once
                    refuse(e.name + " " + std::to_string(i) + ": " + p.name + " claims " + std::to_string(count) +
                           " entries, more than the rest of the file holds");
                if (indices) polygon.clear();
                for (unsigned long long k = 0; k < count; ++k) {
                    if (!readValue(p.type, indices, &v, &word))
                        refuse(where() + e.name + " " + std::to_string(i) + ": " + p.name + " claims " +
                               std::to_string(count) + " entries, the file ends after " + std::to_string(k));
                    if (indices) polygon.push_back(v >= 0 && v <= double(INT32_MAX) ? (long long)v : -1);
                }
                if (indices) addPolygon(mesh, polygon);
            }
            if (isVertex) mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
        }
        if (isFace) break;  // as OpenMesh: what follows the faces is not read
    }
    checkIndices(mesh);
    return mesh;
}

TriangleMesh readOffBytes(const std::string& bytes) {
    TextWords words(bytes, 0, true);
    const std::optional<std::string_view> keyword = words.next();
    if (!keyword) refuse("not an OFF file (no OFF keyword)");
    std::string_view k = *keyword;
    const long long keywordLine = words.line();
    bool colours = false, normals = false, texcoords = false;
    const auto prefix = [&](std::string_view letters) {
        if (!k.starts_with(letters)) return false;
        k.remove_prefix(letters.size());
        return true;
    };
    texcoords = prefix("ST");
    colours = prefix("C");
    normals = prefix("N");
    if (k.starts_with("4") || k.starts_with("n")) refuse("OFF files of other than three dimensions are not supported");
    if (k != "OFF") refuse("not an OFF file (no OFF keyword)");

    TriangleMesh mesh;
    std::vector<long long> polygon;
    TextWords probe = words;
    const std::optional<std::string_view> second = probe.next();
    if (second && *second == "BINARY" && probe.line() == keywordLine) {
        // OpenMesh's binary OFF: after the keyword line, little-endian int32 counts, then per
        // vertex 3 floats (+3 normal floats, +3 colour ints, +2 texture floats), per face a
        // count and that many int32 indices.
        const size_t nl = bytes.find('\n');
        if (nl == std::string::npos) refuse("the binary OFF header is cut short");
        PlyBytes in(bytes, nl + 1, false);
        const auto number = [&](PlyType t, const std::string& what) {
            const std::optional<double> v = in.value(t);
            if (!v) refuse("the file ends before " + what + " (it is cut short, or a count in it is wrong)");
            return *v;
        };
        const double nV = number(PlyType::Int32, "the counts"), nF = number(PlyType::Int32, "the counts");
        number(PlyType::Int32, "the counts");
        if (nV < 0 || nF < 0) refuse("the OFF header's vertex or face count is negative");
        const size_t extra = (normals ? 3 : 0) + (colours ? 3 : 0) + (texcoords ? 2 : 0);
        if (!in.has(size_t(nV) * (3 + extra) * 4)) refuse("the file is shorter than its " + std::to_string(size_t(nV)) + " vertices");
        for (size_t i = 0; i < size_t(nV); ++i) {
            float xyz[3];
            for (float& c : xyz) {
                c = float(number(PlyType::Float32, "vertex " + std::to_string(i)));
                if (!std::isfinite(c)) refuse("vertex " + std::to_string(i) + " has a coordinate that is not finite");
            }
            in.skip(extra * 4);
            mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
        }
        for (size_t f = 0; f < size_t(nF); ++f) {
            const double n = number(PlyType::Int32, "face " + std::to_string(f));
            if (n < 0 || !in.has(size_t(n) * 4))
                refuse("face " + std::to_string(f) + " claims " + std::to_string((long long)n) +
                       " vertices, more than the rest of the file holds");
            polygon.clear();
            for (size_t j = 0; j < size_t(n); ++j) polygon.push_back((long long)number(PlyType::Int32, "an index"));
            addPolygon(mesh, polygon);
        }
        checkIndices(mesh);
        return mesh;
    }

    const auto count = [&](const char* what) {
        const std::optional<std::string_view> w = words.next();
        if (!w) refuse(std::string("the file ends before the ") + what);
        const std::optional<long long> n = parseInteger(*w);
        if (!n || *n < 0)
            refuse("line " + std::to_string(words.line()) + ": the " + what + " \"" + printableWord(*w) + "\" is not a count");
        return *n;
    };
    const long long nV = count("vertex count"), nF = count("face count");
    count("edge count");
    mesh.vertices.reserve(size_t(std::min<long long>(nV, (long long)bytes.size() / 6)));
    for (long long i = 0; i < nV; ++i) {
        // As OpenMesh: three coordinates, then the rest of their line (normal, colour, texture).
        float xyz[3];
        for (float& c : xyz) {
            const std::optional<std::string_view> w = words.next();
            if (!w)
                refuse("the file ends inside vertex " + std::to_string(i) + " of " + std::to_string(nV) +
                       " (it is cut short, or the vertex count is wrong)");
            std::string problem;
            const std::optional<float> v = parseCoordinate(*w, &problem);
            if (!v) refuse("line " + std::to_string(words.line()) + ": vertex " + std::to_string(i) + ": " + problem);
            c = *v;
        }
        words.skipLine();
        mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    for (long long f = 0; f < nF; ++f) {
        const std::optional<std::string_view> w = words.next();
        if (!w)
            refuse("the file ends before face " + std::to_string(f) + " of " + std::to_string(nF) +
                   " (it is cut short, or the face count is wrong)");
        const long long line = words.line();
        const std::optional<long long> n = parseInteger(*w);
        if (!n || *n < 0)
            refuse("line " + std::to_string(line) + ": face " + std::to_string(f) + ": \"" + printableWord(*w) +
                   "\" is not a vertex count");
        // Indices are read one by one: a count the file cannot hold ends where the file does.
        polygon.clear();
        for (long long j = 0; j < *n; ++j) {
            const std::optional<std::string_view> index = words.next();
            if (!index)
                refuse("line " + std::to_string(line) + ": face " + std::to_string(f) + " claims " + std::to_string(*n) +
                       " vertices, the file ends after " + std::to_string(j));
            const std::optional<long long> i = parseInteger(*index);
            if (!i)
                refuse("line " + std::to_string(words.line()) + ": face " + std::to_string(f) + ": \"" +
                       printableWord(*index) + "\" is not a vertex index");
            polygon.push_back(*i >= 0 && *i <= INT32_MAX ? *i : -1);
        }
        if (*n > 0) words.skipLine();  // a face colour, if any
        addPolygon(mesh, polygon);
    }
    checkIndices(mesh);
    return mesh;
}

}  // namespace lucerna
