// Lucerna's OBJ and STL readers (issue 41, core/mesh/obj_file.h, stl_file.h): the OBJ features
// read as OpenMesh read them (relative indices, v/vt/vn corners, polygons fanned, groups and
// materials skipped, repeated vertices dropped, continued lines); each class of bad input
// refused with one line naming the line; work that grows with the file (a polygon of 100000
// corners, an STL fan of 40000 triangles around one vertex, which took OpenMesh 21 s).

#include "core/mesh/obj_file.h"
#include "core/mesh/stl_file.h"

#include <QtTest>

#include <chrono>
#include <cstring>

using namespace lucerna;

namespace {

// The reason readObjBytes gives, or "" when it reads the text.
QString objRefusal(const std::string& text) {
    try {
        readObjBytes(text);
    } catch (const std::runtime_error& e) {
        return QString::fromUtf8(e.what());
    }
    return {};
}

QString stlRefusal(const std::string& bytes) {
    try {
        readStlBytes(bytes);
    } catch (const std::runtime_error& e) {
        return QString::fromUtf8(e.what());
    }
    return {};
}

std::string binaryStl(const std::vector<std::array<float, 9>>& facets) {
    std::string out(80, ' ');
    const uint32_t n = uint32_t(facets.size());
    out.append(reinterpret_cast<const char*>(&n), 4);
    for (const auto& f : facets) {
        out.append(12, '\0');  // the normal
        out.append(reinterpret_cast<const char*>(f.data()), 36);
        out.append(2, '\0');
    }
    return out;
}

double secondsFor(const std::function<void()>& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

class TestObjFile : public QObject {
    Q_OBJECT
private slots:
    void readsEveryFeature();
    void indicesMayLieAheadOfTheirVertices();
    void refusesBadInput_data();
    void refusesBadInput();
    void workGrowsWithTheFile();
    void readsStl();
    void refusesBadStl_data();
    void refusesBadStl();
};

void TestObjFile::readsEveryFeature() {
    const std::string text =
        "# a comment line\r\n"
        "mtllib first.mtl  second.mtl # the libraries\n"
        "o thing\n"
        "g walls\n"
        "s 1\n"
        "v 0 0 0 1\n"                // w
        "v 1 0 0 0.5 0.25 0.125\n"   // a vertex colour
        "  v +1 1 0\n"
        "v 0 1 0 # a comment after a vertex\n"
        "vt 0 0\nvt 1 0\nvt 1 1\n"
        "vn 0 0 1\n"
        "usemtl red\n"
        "f 1/1/1 2/2/1 3/3/1 4/1/1\n"  // a quad: two triangles from its first corner
        "v 0.1 0.2 0.3\n"
        "v 2 \\\n 2 2\n"                  // continued on the next line
        "g floor\n"
        "f -1//-1 -3 -4/-3\n"              // relative: the 6th, 4th and 3rd vertices
        "f 1 2 1 3 2 # repeated vertices are dropped after their first corner\n"
        "f 5 5 5\n"                         // nothing left: skipped
        "f 2 3 \\\n 5\n"
        "s off\n";
    const ObjMesh obj = readObjBytes(text);
    const TriangleMesh& m = obj.mesh;
    QCOMPARE(m.vertices.size(), size_t(6));
    QCOMPARE(m.vertices[2], V3d(1, 1, 0));
    QCOMPARE(m.vertices[4], V3d(double(0.1f), double(0.2f), double(0.3f)));  // through single precision
    QCOMPARE(m.vertices[5], V3d(2, 2, 2));
    QCOMPARE(m.triangles, (std::vector<V3i>{V3i(0, 1, 2), V3i(0, 2, 3), V3i(5, 3, 2), V3i(0, 1, 2), V3i(1, 2, 4)}));
    QCOMPARE(obj.materialLibraries, (std::vector<std::string>{"first.mtl  second.mtl"}));
}

void TestObjFile::indicesMayLieAheadOfTheirVertices() {
    // OpenMesh read every vertex before the faces, and so does a file that lists faces first.
    const ObjMesh obj = readObjBytes("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    QCOMPARE(obj.mesh.triangles, (std::vector<V3i>{V3i(0, 1, 2)}));
}

void TestObjFile::refusesBadInput_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("expected");
    const QByteArray tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    // The six bytes that aborted the process in OpenMesh's reader (issue 41).
    QTest::newRow("corner that is a comment") << QByteArray("f # /5") << "line 1: the face has 0 corners before the comment \"# /5\"";
    QTest::newRow("comment after two corners") << tri + "f 1 2 # 3" << "line 4: the face has 2 corners before the comment";
    QTest::newRow("two corners") << tri + "f 1 2" << "line 4: the face has 2 corners, a face needs three or more";
    QTest::newRow("corner without vertex") << tri + "f /1 2 3" << "line 4: face corner \"/1\" has no vertex index";
    QTest::newRow("index zero") << tri + "f 0 1 2" << "line 4: face corner \"0\": the vertex index is 0";
    QTest::newRow("index beyond the file") << tri + "f 1 2 4\n" << "line 4: a corner names vertex 4, the file has 3 vertices";
    QTest::newRow("relative index before the first") << tri + "f -1 -2 -4"
                                                     << "line 4: face corner \"-4\": the vertex index -4 reaches before the first vertex";
    QTest::newRow("index beyond 32 bits") << tri + "f 1 2 3000000000" << "the vertex index 3000000000 is beyond any file";
    QTest::newRow("index not an integer") << tri + "f 1 2 3.0" << "line 4: face corner \"3.0\": the vertex index \"3.0\" is not an integer";
    QTest::newRow("index of letters") << tri + "f 1 2 x" << "the vertex index \"x\" is not an integer";
    QTest::newRow("four parts") << tri + "f 1/1/1/1 2 3" << "face corner \"1/1/1/1\" has more than three parts";
    QTest::newRow("texture coordinate beyond the file") << tri + "vt 0 0\nf 1/2 2/1 3/1"
                                                        << "line 5: a corner names texture coordinate 2, the file has 1 texture coordinate";
    QTest::newRow("normal beyond the file") << tri + "f 1//1 2//1 3//1" << "line 4: a corner names normal 1, the file has 0 normals";
    QTest::newRow("relative normal before the first") << tri + "vn 0 0 1\nf 1//-2 2//1 3//1" << "the normal index -2 reaches before";
    QTest::newRow("texture index zero") << tri + "vt 0 0\nf 1/0 2/1 3/1" << "line 5: face corner \"1/0\": the texture coordinate index is 0";
    QTest::newRow("vertex letters") << QByteArray("v 0 a 0") << "line 1: vertex coordinate \"a\" is not a number";
    QTest::newRow("vertex nan") << QByteArray("\nv nan 0 0") << "line 2: vertex coordinate nan is not a finite number";
    QTest::newRow("vertex beyond single precision") << QByteArray("v 1e39 0 0") << "1e39 lies beyond single-precision range";
    QTest::newRow("vertex colour of letters") << QByteArray("v 0 0 0 red") << "\"red\" is not a number";
    QTest::newRow("vertex of two coordinates") << QByteArray("v 1 2 # 3") << "the vertex has fewer than three coordinates";
    QTest::newRow("texture coordinate of letters") << QByteArray("vt u v") << "line 1: texture coordinate \"u\" is not a number";
    QTest::newRow("normal of two coordinates") << QByteArray("vn 0 1") << "the normal has fewer than three coordinates";
    QTest::newRow("absurd line") << QByteArray("g ") + QByteArray(int(kLongestObjLine), 'x') << "line 1: the line is longer than 1048576 bytes";
    QByteArray continued = tri;
    for (int i = 0; i < 20000; ++i) continued += "1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 \\\n";
    QTest::newRow("absurd continued line") << "\n" + continued << "line 5: the line is longer than";
    QTest::newRow("binary bytes") << QByteArray("v \x01\xff\x00 0 0", 9) << "\"\\x01\\xff\\x00\" is not a number";
}

void TestObjFile::refusesBadInput() {
    QFETCH(QByteArray, text);
    QFETCH(QString, expected);
    const QString why = objRefusal(text.toStdString());
    QVERIFY2(why.contains(expected), qPrintable("got: " + why + "\nexpected: " + expected));
    QVERIFY2(!why.contains('\n') && why.size() < 300, qPrintable(why));
}

void TestObjFile::workGrowsWithTheFile() {
    // One polygon of 100000 corners, each vertex named twice (dropping the repeats is n log n).
    std::string text;
    const int n = 50000;
    for (int i = 0; i < n; ++i) text += "v " + std::to_string(i) + " 0 0\n";
    text += "f";
    for (int round = 0; round < 2; ++round)
        for (int i = 1; i <= n; ++i) text += " " + std::to_string(i);
    TriangleMesh m;
    QVERIFY(secondsFor([&] { m = readObjBytes(text).mesh; }) < 2.0);
    QCOMPARE(m.triangles.size(), size_t(n - 2));
    QCOMPARE(m.triangles.back(), V3i(0, n - 2, n - 1));

    // 40000 STL triangles around one vertex: OpenMesh's half-edge building took 21 s.
    std::vector<std::array<float, 9>> fan;
    for (int i = 0; i < 40000; ++i) fan.push_back({0, 0, 0, float(i + 1), 0, 0, float(i + 1), 1, 0});
    const std::string stl = binaryStl(fan);
    QVERIFY(secondsFor([&] { m = readStlBytes(stl); }) < 2.0);
    QCOMPARE(m.triangles.size(), size_t(40000));
    QCOMPARE(m.vertices.size(), size_t(80001));
}

void TestObjFile::readsStl() {
    // Corners at one position are one vertex (0 and -0 too); a facet on two vertices is skipped.
    const std::string ascii =
        "solid two\r\n facet normal 0 0 1\r\n  outer loop\r\n   vertex 0 0 0\r\n   vertex 1 0 0\r\n   vertex 0 1 0\r\n"
        "  endloop\r\n endfacet\r\n"
        " FACET NORMAL nan nan nan\n  OUTER LOOP\n   VERTEX 1 0 0\n   VERTEX -0 0 0\n   VERTEX 0 0 1\n  ENDLOOP\n ENDFACET\n"
        " facet normal 0 0 0\n  outer loop\n   vertex 1 0 0\n   vertex 1 0 0\n   vertex 0 0 1\n  endloop\n endfacet\n"
        "endsolid two\nsolid more\nendsolid more\n";
    TriangleMesh m = readStlBytes(ascii);
    QCOMPARE(m.vertices, (std::vector<V3d>{V3d(0, 0, 0), V3d(1, 0, 0), V3d(0, 1, 0), V3d(0, 0, 1)}));
    QCOMPARE(m.triangles, (std::vector<V3i>{V3i(0, 1, 2), V3i(1, 0, 3)}));
    // Binary: the same facets; a header that starts with "solid" is still binary by its size.
    std::string binary = binaryStl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, -0.0f, 0, 0, 0, 0, 1}, {1, 0, 0, 1, 0, 0, 0, 0, 1}});
    binary.replace(0, 5, "solid");
    QCOMPARE(readStlBytes(binary), m);
}

void TestObjFile::refusesBadStl_data() {
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("expected");
    const QByteArray facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
    QTest::newRow("neither binary nor ASCII") << QByteArray(100, '\x07') << "not an STL file";
    QTest::newRow("cut short") << "solid s\n" + facet.left(40) << "the file ends inside a vertex (it is cut short)";
    QTest::newRow("vertex of letters") << "solid s\n" + QByteArray(facet).replace("vertex 1 0 0", "vertex 1 a 0")
                                       << "line 5: vertex coordinate \"a\" is not a number";
    QTest::newRow("vertex beyond single precision") << "solid s\n" + QByteArray(facet).replace("vertex 1 0 0", "vertex 1e39 0 0")
                                                    << "lies beyond single-precision range";
    QTest::newRow("four corners") << "solid s\n" + QByteArray(facet).replace("endloop", "vertex 1 1 0\nendloop")
                                  << "line 7: \"vertex\" where the facet needs \"endloop\"";
    QTest::newRow("stray word") << "solid s\n" + facet + "junk\n" << "line 9: \"junk\" where a facet (or endsolid) should start";
    const float nan = std::numeric_limits<float>::quiet_NaN();
    QTest::newRow("binary nan") << QByteArray::fromStdString(binaryStl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, nan, 0, 1, 0, 0, 0, 1, 0}}))
                                << "triangle 1 has a corner that is not a finite point";
}

void TestObjFile::refusesBadStl() {
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    const QString why = stlRefusal(bytes.toStdString());
    QVERIFY2(why.contains(expected), qPrintable("got: " + why + "\nexpected: " + expected));
    QVERIFY2(!why.contains('\n') && why.size() < 300, qPrintable(why));
}

QTEST_GUILESS_MAIN(TestObjFile)
#include "test_obj_file.moc"
