#include "core/mesh/mesh_file.h"
#include "core/atomic_file.h"
#include "core/mesh/mesh_file_formats.h"
#include "core/mesh/obj_file.h"
#include "core/mesh/stl_file.h"

#include <QFileInfo>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lucerna {

namespace {

bool isPlyScalar(const std::string& type) {
    static const char* const kTypes[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                         "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
    for (const char* t : kTypes)
        if (type == t) return true;
    return false;
}

// OpenMesh's PLY reader trusts its header: a malformed line crashes it, and a header without its
// end_header line makes it loop forever. So the header is parsed strictly here first.
std::string plyHeaderProblem(const std::string& head, long long fileSize) {
    const size_t end = head.find("\nend_header");
    if (head.rfind("ply", 0) != 0) return "not a PLY file (it does not start with \"ply\")";
    const std::string_view after = std::string_view(head).substr(std::min(head.size(), end + 11), 2);
    if (end == std::string::npos || !(after.starts_with('\n') || after == "\r\n"))
        return "the PLY header has no end_header line";
    std::istringstream lines(head.substr(0, end + 1));
    std::string line;
    std::getline(lines, line);  // "ply"
    bool format = false, vertex = false, face = false;
    std::string element;
    std::vector<std::string> vertexProperties;
    for (int number = 2; std::getline(lines, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string word; words >> word;) w.push_back(word);
        const auto bad = [&] { return "line " + std::to_string(number) + " of the PLY header is malformed"; };
        if (w.empty()) return bad();
        if (w[0] == "comment" || w[0] == "obj_info") continue;
        if (w[0] == "format") {
            if (w.size() != 3 || w[2] != "1.0" || format || !element.empty() ||
                (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
                return bad();
            format = true;
        } else if (w[0] == "element") {
            long double count = -1;
            if (w.size() != 3 || !(std::istringstream(w[2]) >> count) || !(count >= 0 && count <= fileSize) ||
                count != std::floor(count))
                return bad();
            element = w[1];
            vertex = vertex || element == "vertex";
        } else if (w[0] == "property" && !element.empty()) {
            const bool list = w.size() == 5 && w[1] == "list" && isPlyScalar(w[2]) && isPlyScalar(w[3]);
            if (!list && !(w.size() == 3 && isPlyScalar(w[1]))) return bad();
            if (element == "vertex") vertexProperties.push_back(list ? std::string() : w[2]);
            if (element == "face" && list && (w[4] == "vertex_indices" || w[4] == "vertex_index")) face = true;
        } else {
            return bad();
        }
    }
    if (!format) return "the PLY header has no format line";
    const auto has = [&](const char* name) {
        return std::find(vertexProperties.begin(), vertexProperties.end(), name) != vertexProperties.end();
    };
    if (!vertex || !has("x") || !has("y") || !has("z")) return "the PLY file has no vertex positions (x, y, z)";
    if (!face) return "the PLY file has no faces (no vertex_indices list)";
    return {};
}

// Element counts beyond the file's size would make OpenMesh reserve absurd amounts of memory, and
// malformed PLY headers crash it; such files are refused before OpenMesh sees them. Returns the
// problem, or nothing.
std::string headerProblem(const std::string& path, const std::string& ext, long long fileSize) {
    if (ext != "ply" && ext != "off") return {};
    std::ifstream in(path, std::ios::binary);
    std::string head(size_t(std::min<long long>(fileSize, 1 << 16)), '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(std::max<std::streamsize>(in.gcount(), 0)));
    if (ext == "ply") return plyHeaderProblem(head, fileSize);
    // Every element needs at least one byte, so no count can exceed the file's size.
    const auto implausible = [&](long double count) { return !(count >= 0 && count <= fileSize); };

    // OFF: a keyword ending in OFF (COFF, NOFF, STOFF, ...), optionally BINARY, then the vertex
    // and face counts, as text or as 32-bit integers; '#' starts a comment.
    std::istringstream text(head);
    std::string word;
    while (text >> word && word[0] == '#') std::getline(text, word);
    if (word.size() < 3 || word.compare(word.size() - 3, 3, "OFF") != 0) return "not an OFF file (no OFF keyword)";
    if (word.find('n') != std::string::npos) text >> word;  // nOFF: the dimension comes first
    long double counts[2] = {-1, -1};
    const std::streampos afterKeyword = text.tellg();
    if (text >> word && word == "BINARY") {
        const size_t at = head.find('\n', size_t(text.tellg()));
        if (at == std::string::npos || at + 1 + 8 > head.size()) return "the binary OFF header is cut short";
        for (int i = 0; i < 2; ++i) {
            int32_t n = 0;
            std::memcpy(&n, head.data() + at + 1 + 4 * i, 4);
            counts[i] = n;
        }
    } else {
        text.clear();
        text.seekg(afterKeyword);
        for (long double& c : counts) {
            while (text >> word && word[0] == '#') std::getline(text, word);
            std::istringstream number(word);
            number >> c;
        }
    }
    if (implausible(counts[0]) || implausible(counts[1])) return "the OFF header's vertex or face count is implausible";
    return {};
}

}  // namespace

TriangleMesh readMeshFile(const std::string& absolutePath) {
    const auto fail = [&](const std::string& why) { throw std::runtime_error(absolutePath + ": " + why); };
    if (absolutePath.find('\0') != std::string::npos) fail("the path contains a NUL character");
    const QFileInfo info(QString::fromStdString(absolutePath));
    if (!info.exists()) fail("no such file");
    if (!info.isFile()) fail("not a regular file");
    if (!info.isReadable()) fail("not readable (permission denied)");
    const std::string ext = info.suffix().toLower().toStdString();
    if (ext != "obj" && ext != "ply" && ext != "off" && ext != "stl")
        fail("unsupported mesh format \"" + ext + "\" (expected obj, ply, off or stl)");

    if (const std::string problem = headerProblem(absolutePath, ext, info.size()); !problem.empty()) fail(problem);

    // Every format is read here from the file's bytes (mesh_file_formats.h, obj_file.h and
    // stl_file.h say why no library reads them).
    TriangleMesh out;
    std::string problem;
    try {
        std::string bytes(size_t(info.size()), '\0');
        std::ifstream in(absolutePath, std::ios::binary);
        in.read(bytes.data(), std::streamsize(bytes.size()));
        bytes.resize(size_t(std::max<std::streamsize>(in.gcount(), 0)));
        if (ext == "ply") out = readPlyBytes(bytes);
        else if (ext == "off") out = readOffBytes(bytes);
        else if (ext == "obj") out = readObjBytes(bytes).mesh;
        else out = readStlBytes(bytes);
    } catch (const std::bad_alloc&) {
        problem = "the file is too large to read into memory";
    } catch (const std::runtime_error& e) {
        problem = e.what();
    }
    if (!problem.empty()) fail(problem);
    if (out.triangles.empty()) fail("the file has no faces");
    return out;
}

void writePlyFile(const std::string& path, const TriangleMesh& mesh) {
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by Lucerna\n";
    out += "element vertex " + std::to_string(mesh.vertices.size()) + "\n";
    out += "property double x\nproperty double y\nproperty double z\n";
    out += "element face " + std::to_string(mesh.triangles.size()) + "\n";
    out += "property list uchar int vertex_indices\nend_header\n";
    static_assert(std::endian::native == std::endian::little, "PLY bytes are written in host order");
    const auto append = [&](const auto& value) {
        const char* bytes = reinterpret_cast<const char*>(&value);
        out.append(bytes, sizeof value);
    };
    for (const V3d& v : mesh.vertices) {
        append(v.x);
        append(v.y);
        append(v.z);
    }
    for (const V3i& t : mesh.triangles) {
        append(uint8_t(3));
        append(int32_t(t.x));
        append(int32_t(t.y));
        append(int32_t(t.z));
    }
    writeTextAtomically(path, out);
}

}  // namespace lucerna
