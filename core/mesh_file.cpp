#include "core/mesh_file.h"

// MeshIO.hh must come before the mesh kernel headers (OpenMesh registers its readers that way).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <QFileInfo>

#include <mutex>
#include <stdexcept>

namespace lucerna {

namespace {

struct PolyTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;  // keep what a PLY file stores in doubles
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<PolyTraits>;

// OpenMesh's own importer drops faces with a repeated vertex, and re-creates the vertices of a
// face that would make the mesh non-manifold (a third face on an edge, a flipped neighbour) at
// new indices. SPEC.md wants every face of the file, with its vertices in file order, so this
// importer records each vertex and each polygon exactly as the reader hands them over, before
// OpenMesh builds its half-edge connectivity (which the PolyMesh still gets, so that the readers
// see valid faces). The vertices OpenMesh duplicates never reach the result.
class RecordingImporter : public OpenMesh::IO::ImporterT<PolyMesh> {
public:
    using Base = OpenMesh::IO::ImporterT<PolyMesh>;
    using Base::add_face;
    using Base::add_vertex;

    explicit RecordingImporter(PolyMesh& mesh) : Base(mesh) {}

    // The PLY reader adds a vertex first and sets its position later, so positions are read
    // from the mesh at the end; only the handles are recorded here.
    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override { return record(Base::add_vertex(p)); }
    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override { return record(Base::add_vertex(p)); }
    OpenMesh::VertexHandle add_vertex() override { return record(Base::add_vertex()); }

    OpenMesh::FaceHandle add_face(const VHandles& indices) override {
        if (indices.size() >= 3) {
            std::vector<int> polygon;
            polygon.reserve(indices.size());
            for (const auto& vh : indices) {
                const int i = vh.is_valid() && size_t(vh.idx()) < fileIndex_.size() ? fileIndex_[size_t(vh.idx())] : -1;
                if (i < 0) badIndex = true;
                polygon.push_back(i);
            }
            polygons.push_back(std::move(polygon));
        }
        return Base::add_face(indices);
    }

    std::vector<OpenMesh::VertexHandle> vertices;  // the file's vertices, in file order
    std::vector<std::vector<int>> polygons;        // in file order, indices into `vertices`
    bool badIndex = false;

private:
    OpenMesh::VertexHandle record(OpenMesh::VertexHandle vh) {
        if (!vh.is_valid()) return vh;
        if (fileIndex_.size() <= size_t(vh.idx())) fileIndex_.resize(size_t(vh.idx()) + 1, -1);
        fileIndex_[size_t(vh.idx())] = int(vertices.size());
        vertices.push_back(vh);
        return vh;
    }

    std::vector<int> fileIndex_;  // OpenMesh's vertex index -> index in `vertices`
};

// OpenMesh reports trouble on its own streams (stderr), including harmless notes on every
// non-manifold face; readMeshFile reports failures itself, so those streams are silenced once.
// OpenMesh's readers are singletons that keep per-read state, so reads take turns.
std::mutex& openMeshLock() {
    static std::mutex lock;
    static std::once_flag silenced;
    std::call_once(silenced, [] {
        omerr().disable();
        omlog().disable();
        omout().disable();
    });
    return lock;
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

    PolyMesh mesh;
    RecordingImporter importer(mesh);
    {
        std::lock_guard guard(openMeshLock());
        OpenMesh::IO::Options options;  // positions and faces only: no normals, colours, UVs
        if (!OpenMesh::IO::IOManager().read(absolutePath, importer, options))
            fail("not a valid " + ext + " file (OpenMesh could not read it)");
    }
    if (importer.badIndex) fail("a face refers to a vertex that does not exist");
    if (importer.polygons.empty()) fail("the file has no faces");

    TriangleMesh out;
    out.vertices.reserve(importer.vertices.size());
    for (const OpenMesh::VertexHandle vh : importer.vertices) {
        const auto& p = mesh.point(vh);
        out.vertices.emplace_back(p[0], p[1], p[2]);
    }
    for (const std::vector<int>& polygon : importer.polygons)
        for (size_t k = 1; k + 1 < polygon.size(); ++k)
            out.triangles.emplace_back(polygon[0], polygon[k], polygon[k + 1]);
    return out;
}

}  // namespace lucerna
