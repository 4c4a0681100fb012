// Mesh files in scenes (SPEC.md section 1, core/mesh/mesh_file.h): each format read, a missing
// or broken file rejected with its one-line message, non-manifold files kept face by face,
// upper-case extensions, nothing on stderr, degenerate triangles dropped and counted, and meshes
// resolved again after an edit. The rest of the scene file: test_scene_io.

#include "core/mesh/mesh_file.h"
#include "core/scene/scene_io.h"
#include "scene_text.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cstdio>
#include <unistd.h>

using namespace lucerna;
using namespace lucerna::test;

class TestMeshFiles : public QObject {
    Q_OBJECT

private slots:
    void rejectsMissingOrBadMeshFiles();
    void readsMeshFiles_data();
    void readsMeshFiles();
    void keepsEveryFaceOfNonManifoldFiles();
    void readsUpperCaseExtensionsAndDropsNothingOnStderr();
    void dropsDegenerateTrianglesWithCount();
    void resolveMeshesAfterAnEdit();
};

void TestMeshFiles::rejectsMissingOrBadMeshFiles() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string scenePath = dir.filePath("scene.json").toStdString();
    QFile garbage(dir.filePath("garbage.ply"));
    QVERIFY(garbage.open(QIODevice::WriteOnly));
    garbage.write("this is not a ply file\n");
    garbage.close();
    Parts p;
    p.objects = meshObject(R"({"file": "garbage.ply"})");
    std::string message = rejection(p.text(), scenePath);
    QVERIFY2(message.starts_with(scenePath + ": objects[0].mesh.file: cannot load mesh file ") &&
                 message.find("not a PLY file") != std::string::npos, message.c_str());

    QFile noFaces(dir.filePath("points.off"));
    QVERIFY(noFaces.open(QIODevice::WriteOnly));
    noFaces.write("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    noFaces.close();
    p.objects = meshObject(R"({"file": "points.off"})");
    message = rejection(p.text(), scenePath);
    QVERIFY2(message.starts_with(scenePath + ": objects[0].mesh.file: ") && message.find("no faces") != std::string::npos,
             message.c_str());

    QFile unreadable(dir.filePath("secret.obj"));
    QVERIFY(unreadable.open(QIODevice::WriteOnly));
    unreadable.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    unreadable.close();
    QVERIFY(unreadable.setPermissions(QFileDevice::Permissions()));
    if (::geteuid() != 0) {  // root reads anything
        p.objects = meshObject(R"({"file": "secret.obj"})");
        message = rejection(p.text(), scenePath);
        QVERIFY2(message.starts_with(scenePath + ": objects[0].mesh.file: ") && message.find("not readable") != std::string::npos,
                 message.c_str());
    }
}

void TestMeshFiles::readsMeshFiles_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("triangles");
    QTest::newRow("obj polygons") << "polygons.obj" << 6;
    QTest::newRow("ply ascii") << "tetra_ascii.ply" << 4;
    QTest::newRow("ply binary doubles") << "tetra_binary.ply" << 4;
    QTest::newRow("off quads") << "cube.off" << 12;
    QTest::newRow("stl ascii") << "tetra_ascii.stl" << 4;
    QTest::newRow("stl binary") << "tetra_binary.stl" << 4;
}

void TestMeshFiles::readsMeshFiles() {
    QFETCH(QString, file);
    QFETCH(int, triangles);
    const TriangleMesh m = readMeshFile(kData + "/meshes/" + file.toStdString());
    QCOMPARE(int(m.triangles.size()), triangles);
    const auto corner = [&](size_t t, int k) { return m.vertices[size_t(m.triangles[t][k])]; };

    if (file == "polygons.obj") {
        // Quad 1 2 3 4, triangle 2 5 3, pentagon 6..10: fans from each polygon's first vertex.
        QCOMPARE(m.triangles, (std::vector<V3i>{V3i(0, 1, 2), V3i(0, 2, 3), V3i(1, 4, 2), V3i(5, 6, 7), V3i(5, 7, 8), V3i(5, 8, 9)}));
        QCOMPARE(m.vertices[4], V3d(2, 0.5, 0));
        QCOMPARE(m.vertices[8], V3d(3.5, 1.5, 0));
    } else if (file == "cube.off") {
        QCOMPARE(m.vertices.size(), size_t(8));
        QCOMPARE(m.triangles[0], V3i(0, 3, 2));
        QCOMPARE(m.triangles[1], V3i(0, 2, 1));
        QCOMPARE(m.triangles[11], V3i(0, 7, 3));
    } else {
        // The tetrahedron (0,0,0) (1,0,0) (0,1,0) (0,0,1) with outward faces in file order:
        // STL repeats vertices per facet and the reader merges them, so compare positions.
        // The readers hold positions in single precision (as OpenMesh's did), even a PLY file's doubles.
        const V3d offset = file == "tetra_binary.ply" ? V3d(0.1, 0.2, 0.3) : V3d(0, 0, 0);
        const V3d v[4] = {V3d(0, 0, 0), V3d(1, 0, 0), V3d(0, 1, 0), V3d(0, 0, 1)};
        const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
        QCOMPARE(m.vertices.size(), size_t(4));
        for (size_t t = 0; t < 4; ++t)
            for (int k = 0; k < 3; ++k) {
                const V3d exact = v[faces[t][k]] + offset;
                const V3d expected(float(exact.x), float(exact.y), float(exact.z));
                QVERIFY2(corner(t, k) == expected, qPrintable(QString("triangle %1 corner %2").arg(t).arg(k)));
            }
    }
}

void TestMeshFiles::keepsEveryFaceOfNonManifoldFiles() {
    // Three faces on one edge and a face wound against its neighbour: a half-edge structure
    // (OpenMesh's) refuses both, and every face must still arrive, in order, with its winding.
    const TriangleMesh m = readMeshFile(kData + "/meshes/nonmanifold.obj");
    QCOMPARE(m.triangles, (std::vector<V3i>{V3i(0, 1, 2), V3i(1, 0, 3), V3i(0, 1, 4), V3i(2, 0, 5)}));
    QCOMPARE(m.vertices[3], V3d(0.5, -1, 0));
    QCOMPARE(m.vertices[5], V3d(-1, 0.5, 0));
}

void TestMeshFiles::readsUpperCaseExtensionsAndDropsNothingOnStderr() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString upper = dir.filePath("POLYGONS.OBJ");
    QVERIFY(QFile::copy(QString::fromStdString(kData + "/meshes/polygons.obj"), upper));

    // Send stderr to a file while a non-manifold mesh is read (OpenMesh's reader complained there).
    const QString log = dir.filePath("stderr.txt");
    std::fflush(stderr);
    const int saved = ::dup(2);
    FILE* sink = std::fopen(log.toLocal8Bit().constData(), "w");
    QVERIFY(saved >= 0 && sink);
    ::dup2(::fileno(sink), 2);
    size_t triangles = 0;
    try {
        triangles = readMeshFile(upper.toStdString()).triangles.size();
        triangles += readMeshFile(kData + "/meshes/nonmanifold.obj").triangles.size();
        triangles += readMeshFile(kData + "/meshes/tetra_binary.stl").triangles.size();
    } catch (...) {
    }
    std::fflush(stderr);
    ::dup2(saved, 2);
    ::close(saved);
    std::fclose(sink);
    QCOMPARE(triangles, size_t(6 + 4 + 4));
    QCOMPARE(readText(log.toStdString()), std::string());
}

void TestMeshFiles::dropsDegenerateTrianglesWithCount() {
    Parts p;
    // A PLY file with a repeated index and three collinear points (OBJ and STL readers remove
    // repeated indices before anyone sees them), an inline triangle with a
    // repeated vertex, a quad folded onto a line (both halves), and an object with no triangles.
    p.objects = object(R"({"name": "file", "material": "white", "mesh": {"file": "meshes/degenerate.ply"}}, )"
                       R"({"name": "inline", "material": "white", "mesh": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.1, 0.2, 0.3], [0.3, 0.6, 0.9]], "triangles": [[0, 1, 2], [1, 1, 2], [0, 3, 4]]}}, )"
                       R"({"name": "flat quad", "material": "white", "mesh": {"quad": [[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]}}, )"
                       R"({"name": "empty", "material": "white", "mesh": {"vertices": [], "triangles": []}})");
    LoadReport report;
    const Scene s = parseScene(p.text(), kCase, &report);
    QCOMPARE(report.degenerateTrianglesDropped, 2 + 2 + 2);
    QCOMPARE(s.objects[0].worldMesh->triangles, (std::vector<V3i>{V3i(0, 1, 2), V3i(0, 2, 3)}));
    QCOMPARE(s.objects[1].worldMesh->triangles, (std::vector<V3i>{V3i(0, 1, 2)}));
    QVERIFY(s.objects[2].worldMesh->triangles.empty());
    QCOMPARE(report.warnings.size(), size_t(4));
    QCOMPARE(report.warnings[0], kCase + ": objects[0].mesh: dropped 2 of 4 triangles as degenerate (zero area)");
    QCOMPARE(report.warnings[2], kCase + ": objects[2].mesh: dropped 2 of 2 triangles as degenerate (zero area)");
    QCOMPARE(report.warnings[3], kCase + ": objects[3].mesh: the mesh has no triangles");
    // The source keeps what the file says, so that saving loses nothing.
    QCOMPARE(s.objects[1].mesh.inlineMesh.triangles.size(), size_t(3));
}

void TestMeshFiles::resolveMeshesAfterAnEdit() {
    Scene s = loadScene(kData + "/every-key.json");
    const auto before = s.objects[5].worldMesh;  // the cube, translated by (60, 0, 0)
    QCOMPARE(before->vertices[6], V3d(61, 1, 1));
    s.objects[5].transform->translate = V3d(0, 10, 0);
    resolveMeshes(s);
    QCOMPARE(s.objects[5].worldMesh->vertices[6], V3d(1, 11, 1));
    QCOMPARE(before->vertices[6], V3d(61, 1, 1));  // snapshots holding the old mesh keep it

    // A failure leaves every world mesh as it was.
    const auto kept = s.objects[5].worldMesh;
    s.objects[6].mesh.file = "meshes/gone.stl";
    try {
        resolveMeshes(s);
        QFAIL("a missing mesh file was accepted");
    } catch (const SceneError& e) {
        QVERIFY2(std::string(e.what()).find(": objects[6].mesh.file: cannot load mesh file ") != std::string::npos, e.what());
    }
    QCOMPARE(s.objects[5].worldMesh, kept);
}

QTEST_GUILESS_MAIN(TestMeshFiles)
#include "test_mesh_files.moc"
