// Lucerna's own OBJ and STL readers (core/mesh/obj_file.h, stl_file.h) against the OpenMesh path
// they replaced (issue 41): on the OBJ and STL files of the tests and resources and on generated
// valid ones, readMeshFile gives exactly the vertices (single precision, file order) and
// triangles (order and fans) that OpenMesh's readers, recorded as mesh_file.cpp recorded them,
// gave. Built only where OpenMesh is installed (tests/CMakeLists.txt).

#include "core/mesh/mesh_file.h"

// MeshIO.hh must come before the mesh kernel headers (OpenMesh registers its readers that way).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <random>

using namespace lucerna;

namespace {

const std::string kData = LUCERNA_TEST_DATA_DIR;
const std::string kResources = LUCERNA_RESOURCE_DIR;

// ---- The OpenMesh path, as core/mesh/mesh_file.cpp had it -----------------------------------

struct PolyTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<PolyTraits>;

// Records each vertex and each polygon as the reader hands them over, before OpenMesh's importer
// drops or re-creates any for its half-edge structure.
class RecordingImporter : public OpenMesh::IO::ImporterT<PolyMesh> {
public:
    using Base = OpenMesh::IO::ImporterT<PolyMesh>;
    using Base::add_face;
    using Base::add_vertex;

    explicit RecordingImporter(PolyMesh& mesh) : Base(mesh) {}

    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override { return record(Base::add_vertex(p)); }
    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override { return record(Base::add_vertex(p)); }
    OpenMesh::VertexHandle add_vertex() override { return record(Base::add_vertex()); }

    OpenMesh::FaceHandle add_face(const VHandles& indices) override {
        if (indices.size() >= 3) {
            std::vector<int> polygon;
            for (const auto& vh : indices) {
                const int i = vh.is_valid() && size_t(vh.idx()) < fileIndex_.size() ? fileIndex_[size_t(vh.idx())] : -1;
                if (i < 0) badIndex = true;
                polygon.push_back(i);
            }
            polygons.push_back(std::move(polygon));
        }
        return Base::add_face(indices);
    }

    std::vector<OpenMesh::VertexHandle> vertices;
    std::vector<std::vector<int>> polygons;
    bool badIndex = false;

private:
    OpenMesh::VertexHandle record(OpenMesh::VertexHandle vh) {
        if (!vh.is_valid()) return vh;
        if (fileIndex_.size() <= size_t(vh.idx())) fileIndex_.resize(size_t(vh.idx()) + 1, -1);
        fileIndex_[size_t(vh.idx())] = int(vertices.size());
        vertices.push_back(vh);
        return vh;
    }
    std::vector<int> fileIndex_;
};

TriangleMesh readWithOpenMesh(const std::string& path) {
    static const bool silenced = [] {
        omerr().disable();
        omlog().disable();
        omout().disable();
        return true;
    }();
    (void)silenced;
    PolyMesh mesh;
    RecordingImporter importer(mesh);
    OpenMesh::IO::Options options;
    if (!OpenMesh::IO::IOManager().read(path, importer, options)) throw std::runtime_error("OpenMesh could not read " + path);
    if (importer.badIndex) throw std::runtime_error("OpenMesh: a face refers to a vertex that does not exist");
    TriangleMesh out;
    for (const OpenMesh::VertexHandle vh : importer.vertices) {
        const auto& p = mesh.point(vh);
        out.vertices.emplace_back(p[0], p[1], p[2]);
    }
    for (const std::vector<int>& polygon : importer.polygons)
        for (size_t k = 1; k + 1 < polygon.size(); ++k) out.triangles.emplace_back(polygon[0], polygon[k], polygon[k + 1]);
    return out;
}

// ---- Generated valid files -----------------------------------------------------------------

std::string number(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-100, 100);
    char buf[64];
    switch (rng() % 8) {
    case 0: std::snprintf(buf, sizeof buf, "%.17g", u(rng)); break;       // more digits than a float holds
    case 1: std::snprintf(buf, sizeof buf, "%d", int(rng() % 21) - 10); break;
    case 2: std::snprintf(buf, sizeof buf, "+%.3f", std::abs(u(rng))); break;
    case 3: std::snprintf(buf, sizeof buf, "%.6e", u(rng) * 1e-20); break;
    case 4: std::snprintf(buf, sizeof buf, "%.9g", double(float(u(rng)))); break;
    default: std::snprintf(buf, sizeof buf, "%.4f", u(rng)); break;
    }
    return buf;
}

// An OBJ file of every feature the two readers share: vertices with w or a colour, texture
// coordinates and normals, faces of 3 to 8 corners in every corner form with absolute (also
// ahead of their vertex), relative and repeated indices, groups, objects, smoothing groups,
// materials, comments, blank lines, CRLF and leading blanks.
std::string generatedObj(unsigned seed) {
    std::mt19937 rng(seed);
    const int total = 40 + int(rng() % 60);
    std::string out = "# generated " + std::to_string(seed) + "\nmtllib none.mtl\no thing\n";
    int v = 0, vt = 0, vn = 0;
    const std::string eol = seed % 2 ? "\r\n" : "\n";
    while (v < total || rng() % 4) {
        const unsigned what = rng() % 10;
        if (v < total && (what < 4 || v < 3)) {
            out += (rng() % 5 == 0 ? "  v " : "v ") + number(rng) + " " + number(rng) + " " + number(rng);
            if (rng() % 6 == 0) out += " 1";
            else if (rng() % 6 == 0) out += " 0.5 0.25 1";
            ++v;
        } else if (what == 4) {
            out += "vt " + number(rng) + " " + number(rng) + (rng() % 2 ? " 0" : "");
            ++vt;
        } else if (what == 5) {
            out += "vn " + number(rng) + " " + number(rng) + " " + number(rng);
            ++vn;
        } else if (what == 6) {
            static const char* const kOther[] = {"g group one", "s 1", "s off", "usemtl paint", "# a comment", "", "\to part"};
            out += kOther[rng() % 7];
        } else {
            const int corners = 3 + int(rng() % 6);
            const unsigned form = rng() % 4;  // v, v/vt, v//vn, v/vt/vn (each as the file allows)
            out += "f";
            int previous = 1;
            for (int c = 0; c < corners; ++c) {
                int index = 1 + int(rng() % unsigned(total));  // may lie ahead of the vertices read so far
                if (rng() % 8 == 0) index = previous;           // a repeated vertex
                previous = index;
                std::string corner = index <= v && rng() % 3 == 0 ? std::to_string(index - v - 1) : std::to_string(index);
                if ((form == 1 || form == 3) && vt > 0) corner += "/" + std::to_string(1 + int(rng() % unsigned(vt)));
                else if (form == 2 || form == 3) corner += "/";
                if ((form == 2 || form == 3) && vn > 0) corner += "/-" + std::to_string(1 + int(rng() % unsigned(vn)));
                if (corner.ends_with('/')) corner.pop_back();
                if (corner.ends_with('/')) corner.pop_back();
                out += " " + corner;
            }
        }
        out += eol;
    }
    return out;
}

float stlCoordinate(std::mt19937& rng) {
    // A coarse grid (so that corners meet), with zeros of either sign and numbers near FLT_MIN,
    // where OpenMesh's test of equal positions is not plain equality.
    static const float kSpecial[] = {0.0f, -0.0f, FLT_MIN, -FLT_MIN, 1.5f * FLT_MIN, FLT_MIN / 4, 1e30f, -2.5e-7f};
    if (rng() % 10 == 0) return kSpecial[rng() % 8];
    return float(int(rng() % 7) - 3) * 0.5f + (rng() % 4 == 0 ? float(rng() % 1000) * 1e-3f : 0.0f);
}

// STL facets on a coarse grid (shared corners, degenerate facets), binary or ASCII.
std::string generatedStl(unsigned seed, bool binary) {
    std::mt19937 rng(seed);
    const int count = 50 + int(rng() % 200);
    std::vector<std::array<float, 9>> facets(static_cast<size_t>(count));
    for (auto& f : facets) {
        for (float& c : f) c = stlCoordinate(rng);
        if (rng() % 10 == 0) std::copy(f.begin(), f.begin() + 3, f.begin() + 3);  // two corners at one place
    }
    std::string out;
    if (binary) {
        out = std::string(80, ' ');
        out.replace(0, 12, "solid binary");
        const uint32_t n = uint32_t(count);
        out.append(reinterpret_cast<const char*>(&n), 4);
        for (const auto& f : facets) {
            const float normal[3] = {0, 0, 1};
            out.append(reinterpret_cast<const char*>(normal), 12);
            out.append(reinterpret_cast<const char*>(f.data()), 36);
            out.append(2, '\0');
        }
        return out;
    }
    out = "solid generated\n";
    char buf[160];
    for (const auto& f : facets) {
        out += " facet normal 0 0 1\n  outer loop\n";
        for (int k = 0; k < 3; ++k) {
            std::snprintf(buf, sizeof buf, "   vertex %.9g %.9g %.9g\n", double(f[size_t(3 * k)]), double(f[size_t(3 * k + 1)]),
                          double(f[size_t(3 * k + 2)]));
            out += buf;
        }
        out += "  endloop\n endfacet\n";
    }
    return out + "endsolid generated\n";
}

}  // namespace

class TestMeshParity : public QObject {
    Q_OBJECT
private slots:
    void sameMeshAsOpenMesh_data();
    void sameMeshAsOpenMesh();
};

void TestMeshParity::sameMeshAsOpenMesh_data() {
    QTest::addColumn<QString>("path");
    static QTemporaryDir dir;
    const QStringList filters{"*.obj", "*.stl"};
    for (const QString& folder : {QString::fromStdString(kResources + "/scenes/meshes/office"), QString::fromStdString(kData + "/meshes")})
        for (const QString& f : QDir(folder).entryList(filters, QDir::Files))
            QTest::newRow(qPrintable(f)) << QDir(folder).filePath(f);
    const auto write = [&](const QString& name, const std::string& bytes) {
        QFile f(dir.filePath(name));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(bytes.data(), qint64(bytes.size()));
        QTest::newRow(qPrintable(name)) << dir.filePath(name);
    };
    for (unsigned seed = 1; seed <= 12; ++seed) write(QString("generated-%1.obj").arg(seed), generatedObj(seed));
    for (unsigned seed = 1; seed <= 6; ++seed) {
        write(QString("generated-%1-binary.stl").arg(seed), generatedStl(seed, true));
        write(QString("generated-%1-ascii.stl").arg(seed), generatedStl(seed, false));
    }
}

void TestMeshParity::sameMeshAsOpenMesh() {
    QFETCH(QString, path);
    const TriangleMesh expected = readWithOpenMesh(path.toStdString());
    const TriangleMesh mesh = readMeshFile(path.toStdString());
    QCOMPARE(mesh.vertices.size(), expected.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const V3d a = mesh.vertices[i], b = expected.vertices[i];
        // Bit for bit: 0 and -0 are told apart too.
        QVERIFY2(std::memcmp(&a, &b, sizeof a) == 0,
                 qPrintable(QString("vertex %1: (%2 %3 %4), OpenMesh (%5 %6 %7)").arg(i).arg(a.x, 0, 'g', 17).arg(a.y, 0, 'g', 17)
                                .arg(a.z, 0, 'g', 17).arg(b.x, 0, 'g', 17).arg(b.y, 0, 'g', 17).arg(b.z, 0, 'g', 17)));
    }
    QCOMPARE(mesh.triangles.size(), expected.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        QVERIFY2(mesh.triangles[t] == expected.triangles[t], qPrintable(QString("triangle %1").arg(t)));
    QVERIFY(!mesh.triangles.empty());
}

QTEST_GUILESS_MAIN(TestMeshParity)
#include "test_mesh_parity.moc"
