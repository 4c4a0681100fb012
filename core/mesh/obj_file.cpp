#include "core/mesh/obj_file.h"

#include "core/mesh/mesh_file_formats.h"
#include "core/message_text.h"

#include <algorithm>
#include <climits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace lucerna {

namespace {

[[noreturn]] void refuse(long long line, const std::string& why) {
    throw std::runtime_error("line " + std::to_string(line) + ": " + why);
}

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The file's statements: its lines, each joined with the next while it ends in '\'.
class Statements {
public:
    explicit Statements(std::string_view bytes) : bytes_(bytes) {}

    // The next statement and the number of its first line; false at the end of the file.
    bool next(std::string_view* statement, long long* number) {
        if (at_ >= bytes_.size()) return false;
        *number = line_ + 1;
        joined_.clear();
        for (bool joining = false;; joining = true) {
            size_t end = bytes_.find('\n', at_);
            if (end == std::string_view::npos) end = bytes_.size();
            std::string_view piece = bytes_.substr(at_, end - at_);
            at_ = end + 1;
            ++line_;
            if (piece.ends_with('\r')) piece.remove_suffix(1);
            // A '\' in a comment is the comment's (a Windows folder, say), not a continuation.
            const bool goesOn = piece.ends_with('\\') && piece.find('#') == std::string_view::npos;
            if (goesOn) piece.remove_suffix(1);
            if (joined_.size() + piece.size() > kLongestObjLine)
                refuse(*number, "the line is longer than " + std::to_string(kLongestObjLine) + " bytes");
            if (!joining && (!goesOn || at_ >= bytes_.size())) {
                *statement = piece;
                return true;
            }
            joined_.append(piece).push_back(' ');
            if (!goesOn || at_ >= bytes_.size()) {
                *statement = joined_;
                return true;
            }
        }
    }

private:
    std::string_view bytes_;
    size_t at_ = 0;
    long long line_ = 0;
    std::string joined_;
};

// Splits a statement into its words, up to a comment; returns the comment ('#' and what follows).
std::string_view split(std::string_view statement, std::vector<std::string_view>& words) {
    words.clear();
    for (size_t i = 0; i < statement.size();) {
        if (isBlank(statement[i])) {
            ++i;
            continue;
        }
        if (statement[i] == '#') return statement.substr(i);
        const size_t start = i;
        while (i < statement.size() && !isBlank(statement[i]) && statement[i] != '#') ++i;
        words.push_back(statement.substr(start, i - start));
    }
    return {};
}

// The elements a face corner refers to: vertices, texture coordinates, normals.
struct Elements {
    const char* name;     // "vertex", ...
    const char* plural;   // "vertices", ...
    long long count = 0;  // read so far
    // The furthest index beyond `count` that a corner named, and its line: checked at the end.
    long long ahead = 0;
    long long aheadLine = 0;
};

// What a corner of an element ("face", ...) is called in messages.
std::string cornerName(const std::string& element, std::string_view corner) {
    return element + " corner \"" + printableWord(corner) + "\"";
}

// The 0-based index a corner's part names, counted from the start or (negative) from the last
// element read so far.
long long resolve(std::string_view part, const std::string& element, std::string_view corner, Elements& e, long long line) {
    const auto where = [&] { return cornerName(element, corner) + ": the " + e.name + " index "; };
    const std::optional<long long> i = parseInteger(part);
    if (!i) refuse(line, where() + "\"" + printableWord(part) + "\" is not an integer");
    if (*i == 0) refuse(line, where() + "is 0 (indices count from 1)");
    if (*i < 0) {
        if (-*i > e.count)
            refuse(line, where() + std::to_string(*i) + " reaches before the first " + e.name + " (" +
                             std::to_string(e.count) + " so far)");
        return e.count + *i;
    }
    if (*i > INT_MAX) refuse(line, where() + std::to_string(*i) + " is beyond any file");
    if (*i > e.count && *i > e.ahead) {
        e.ahead = *i;
        e.aheadLine = line;
    }
    return *i - 1;
}

void checkAhead(const Elements& e) {
    if (e.ahead > e.count)
        refuse(e.aheadLine, std::string("a corner names ") + e.name + " " + std::to_string(e.ahead) + ", the file has " +
                                std::to_string(e.count) + " " + (e.count == 1 ? e.name : e.plural));
}

// The numbers of a v, vt or vn statement (`what`: "vertex", ...): `least` or more, each finite in
// single precision; the first three go to `xyz` when given.
void numbers(const std::vector<std::string_view>& words, size_t least, const std::string& what, long long line, float* xyz) {
    if (words.size() < least + 1)
        refuse(line, "the " + what + (least == 3 ? " has fewer than three coordinates" : " has no coordinates"));
    for (size_t k = 1; k < words.size(); ++k) {
        std::string problem;
        const std::optional<float> v = parseCoordinate(words[k], &problem);
        if (!v) refuse(line, what + " coordinate " + problem);
        if (xyz && k <= 3) xyz[k - 1] = *v;
    }
}

// The polygon with each vertex repeated in it dropped after its first corner, as OpenMesh's
// reader did.
void dropRepeatedVertices(std::vector<long long>& polygon) {
    if (polygon.size() <= 16) {
        for (size_t k = 0; k < polygon.size(); ++k)
            polygon.erase(std::remove(polygon.begin() + std::ptrdiff_t(k) + 1, polygon.end(), polygon[k]), polygon.end());
        return;
    }
    // A long polygon: sort (index, corner) pairs so that work grows as n log n, not n squared.
    std::vector<std::pair<long long, size_t>> sorted;
    sorted.reserve(polygon.size());
    for (size_t k = 0; k < polygon.size(); ++k) sorted.emplace_back(polygon[k], k);
    std::sort(sorted.begin(), sorted.end());
    std::vector<bool> repeated(polygon.size(), false);
    for (size_t k = 1; k < sorted.size(); ++k)
        if (sorted[k].first == sorted[k - 1].first) repeated[sorted[k].second] = true;
    size_t kept = 0;
    for (size_t k = 0; k < polygon.size(); ++k)
        if (!repeated[k]) polygon[kept++] = polygon[k];
    polygon.resize(kept);
}

}  // namespace

ObjMesh readObjBytes(std::string_view bytes) {
    ObjMesh out;
    TriangleMesh& mesh = out.mesh;
    Elements vertices{"vertex", "vertices"}, texcoords{"texture coordinate", "texture coordinates"},
        normals{"normal", "normals"};
    std::vector<std::string_view> words;
    std::vector<long long> polygon;
    Statements statements(bytes);
    std::string_view statement;
    long long line = 0;
    while (statements.next(&statement, &line)) {
        const std::string_view comment = split(statement, words);
        if (words.empty()) continue;
        const std::string_view keyword = words[0];
        if (keyword == "v") {
            float xyz[3];
            numbers(words, 3, "vertex", line, xyz);
            if (vertices.count == INT_MAX) refuse(line, "more vertices than a mesh can index");
            mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
            ++vertices.count;
        } else if (keyword == "vt") {
            numbers(words, 1, "texture", line, nullptr);
            ++texcoords.count;
        } else if (keyword == "vn") {
            numbers(words, 3, "normal", line, nullptr);
            ++normals.count;
        } else if (keyword == "f" || keyword == "l" || keyword == "p") {
            // Line and point elements add nothing to the mesh, but their indices are checked as a
            // face's are: Assimp's importer reads them (model_import.cpp checks a file here first).
            const bool face = keyword == "f";
            const std::string element = face ? "face" : keyword == "l" ? "line element" : "point element";
            const size_t corners = words.size() - 1, least = face ? 3 : keyword == "l" ? 2 : 1;
            if (corners < least)
                refuse(line, "the " + element + " has " + std::to_string(corners) + " corner" + (corners == 1 ? "" : "s") +
                                 (comment.empty() ? "" : " before the comment \"" + printableWord(comment) + "\"") + ", a " +
                                 element + " needs " + (least == 3 ? "three" : least == 2 ? "two" : "one") + " or more");
            polygon.clear();
            for (size_t k = 1; k < words.size(); ++k) {
                // v, v/vt, v//vn or v/vt/vn
                const std::string_view corner = words[k];
                std::string_view parts[3];
                size_t n = 0, from = 0;
                for (;;) {
                    const size_t slash = corner.find('/', from);
                    if (n == 3) refuse(line, cornerName(element, corner) + " has more than three parts");
                    parts[n++] = corner.substr(from, slash == std::string_view::npos ? slash : slash - from);
                    if (slash == std::string_view::npos) break;
                    from = slash + 1;
                }
                if (parts[0].empty()) refuse(line, cornerName(element, corner) + " has no vertex index");
                polygon.push_back(resolve(parts[0], element, corner, vertices, line));
                if (!parts[1].empty()) resolve(parts[1], element, corner, texcoords, line);
                if (!parts[2].empty()) resolve(parts[2], element, corner, normals, line);
            }
            if (!face) continue;
            dropRepeatedVertices(polygon);
            for (size_t k = 1; k + 1 < polygon.size(); ++k)
                mesh.triangles.emplace_back(int(polygon[0]), int(polygon[k]), int(polygon[k + 1]));
        } else if (keyword == "mtllib" && words.size() > 1) {
            const char* first = words[1].data();
            out.materialLibraries.emplace_back(first, size_t(words.back().data() + words.back().size() - first));
        }
        // g, o, s, usemtl, vp and the statements of curves and surfaces: nothing for positions.
    }
    checkAhead(vertices);
    checkAhead(texcoords);
    checkAhead(normals);
    return out;
}

}  // namespace lucerna
