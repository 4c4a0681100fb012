// Hostile and faulty files (issue 26): each is refused by the built `lucerna` with exit status 2
// and one line, in under a second of CPU time and under 100 MB of resident memory, whatever its
// header claims; `import` refuses (leaving nothing behind) or writes a scene that loads; paths
// that are not regular files are refused at once; a bad output path is refused before the
// render; Ctrl-C before the scene has loaded gets its message; stale temporaries go.
//
// Every child runs as tests/support/measured_run.h runs it (its own CPU time and peak resident
// set measured, under 4 GB of address space and 20 s of CPU). Under AddressSanitizer the bounds
// are multiplied by kResourceScale (tests/support/sanitizers.h).

#include "measured_run.h"
#include "sanitizers.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace lucerna::test;

namespace {

// The refusal the issue asks for: exit 2, one line, under a second of CPU, under 100 MB.
#define VERIFY_REFUSED(args, dir, expected)                                                                  \
    do {                                                                                                     \
        const QStringList a_ = (args);                                                                       \
        const Run r_ = runLucerna(a_, (dir));                                                                \
        QVERIFY2(r_.exitCode == 2, qPrintable(describe(a_, r_)));                                            \
        QVERIFY2(isOnePrintableLine(r_.err), qPrintable(describe(a_, r_)));                                  \
        QVERIFY2(r_.cpuSeconds < 1.0 * kResourceScale && r_.wallSeconds < 10.0 * kResourceScale,             \
                 qPrintable(describe(a_, r_)));                                                              \
        QVERIFY2(r_.maxRssMb < 100 * kResourceScale, qPrintable(describe(a_, r_)));                          \
        QVERIFY2(QString::fromUtf8(r_.err).contains(expected), qPrintable(describe(a_, r_) + " expected: " + \
                                                                          QString(expected)));               \
    } while (0)

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

const char* const kCamera =
    R"("camera": {"position": [0, 1, -3], "target": [0, 0, 0], "fov_y": 40, "resolution": [8, 8]})";

// A scene with one object whose mesh is `file`.
QByteArray meshScene(const QString& file) {
    return QString(R"({"lucerna": 1, %1, "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
        "objects": [{"name": "m", "material": "white", "mesh": {"file": "%2"}}]})")
        .arg(kCamera, file)
        .toUtf8();
}

// A scene lit by a luminaire file over a floor.
QByteArray luminaireScene(const QString& file) {
    return QString(R"({"lucerna": 1, %1, "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
        "objects": [{"name": "floor", "material": "white", "mesh": {"quad": [[-2,0,-2],[-2,0,2],[2,0,2],[2,0,-2]]}}],
        "lights": [{"name": "l", "type": "luminaire", "file": "%2", "position": [0, 2, 0], "direction": [0, -1, 0]}]})")
        .arg(kCamera, file)
        .toUtf8();
}

QByteArray le32(qint32 v) { return QByteArray(reinterpret_cast<const char*>(&v), 4); }
QByteArray lef(float v) { return QByteArray(reinterpret_cast<const char*>(&v), 4); }

const QByteArray kPlyBinaryHeader = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                                    "property float y\nproperty float z\nelement face 1\n"
                                    "property list int int vertex_indices\nend_header\n";

QByteArray plyBinaryTriangle(qint32 listCount) {
    QByteArray b = kPlyBinaryHeader;
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) b += lef(v);
    b += le32(listCount);
    for (qint32 i : {0, 1, 2}) b += le32(i);
    return b;
}

// A scan-line EXR header claiming width x height float RGB, uncompressed, followed by an offset
// table of one entry per line, each `offset`, and no pixel data.
QByteArray exrWithoutPixels(int width, int height, quint64 offset, const QByteArray& extraAttribute = {}) {
    QByteArray b("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    const auto attribute = [&](const char* name, const char* type, const QByteArray& value) {
        b += QByteArray(name) + '\0' + QByteArray(type) + '\0' + le32(qint32(value.size())) + value;
    };
    QByteArray channels;
    for (const char* c : {"B", "G", "R"}) channels += QByteArray(c) + '\0' + le32(2) + QByteArray(4, '\0') + le32(1) + le32(1);
    channels += '\0';
    const QByteArray box = le32(0) + le32(0) + le32(width - 1) + le32(height - 1);
    attribute("channels", "chlist", channels);
    attribute("compression", "compression", QByteArray(1, '\0'));
    attribute("dataWindow", "box2i", box);
    attribute("displayWindow", "box2i", box);
    attribute("lineOrder", "lineOrder", QByteArray(1, '\0'));
    attribute("pixelAspectRatio", "float", lef(1));
    attribute("screenWindowCenter", "v2f", lef(0) + lef(0));
    attribute("screenWindowWidth", "float", lef(1));
    b += extraAttribute;
    b += '\0';
    for (int y = 0; y < height; ++y) b += QByteArray(reinterpret_cast<const char*>(&offset), 8);
    return b;
}

QString iesWithMultiplier(const QString& multiplier) {
    return "IESNA:LM-63-2002\n[TEST] hostile\n[LUMINAIRE] overflow\nTILT=NONE\n1 1000 " + multiplier +
           " 2 1 1 2 0.1 0.1 0.05\n1.0 1.0 10\n0 90\n0\n100 100\n";
}

// EULUMDAT, one field a line: the conversion factor is line 24.
QString ldtWithConversionFactor(const QString& factor) {
    QString s = "hostile\n1\n1\n1\n0\n2\n90\nreport\nname\nnumber\nx.ldt\ndate\n";
    for (int i = 0; i < 10; ++i) s += "100\n";
    s += "100\n" + factor + "\n0\n1\n1\nLED\n1000\n3000\n90\n20\n";
    for (int i = 0; i < 10; ++i) s += "0.5\n";
    s += "0\n0\n90\n100\n100\n";
    return s;
}

// The files left in `dir` besides `keep`.
}  // namespace

class TestHostileFiles : public QObject {
    Q_OBJECT
private slots:
    void meshCountsBeyondTheFile_data();
    void meshCountsBeyondTheFile();
    void objLinesGiveTheTrueReason_data();
    void objLinesGiveTheTrueReason();
    void objCornerThatIsAComment();
    void stlFanReadsInTime();
    void importRefusesOrWritesALoadableScene_data();
    void importRefusesOrWritesALoadableScene();
    void importToAFolderLeavesNothing();
    void importerCrashIsOneLine();
    void overflowingPhotometryNamesFileAndLine_data();
    void overflowingPhotometryNamesFileAndLine();
    void binaryBytesStayOutOfMessages();
    void nonRegularPathsAreRefusedAtOnce();
    void exrHeaderWithoutPixels_data();
    void exrHeaderWithoutPixels();
    void exrAttributeClaimingGigabytes();
    void staleTemporariesAreRemoved();
    void badOutputPathIsRefusedBeforeRendering();
    void interruptBeforeTheSceneHasLoaded();
};

void TestHostileFiles::meshCountsBeyondTheFile_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("expected");
    // 45 bytes whose face line claims three billion vertices (took 86 s and 4.2 GB).
    QTest::newRow("OFF face of 3000000000") << "big.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3000000000 0 1 2\n")
                                            << "claims 3000000000 vertices";
    // Truncated: a face line claiming a million vertices (was loaded with the rest read as 0).
    QTest::newRow("OFF face cut short") << "short.off" << QByteArray("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000 0 1 2\n")
                                        << "claims 1000000 vertices";
    QTest::newRow("OFF vertices cut short") << "few.off" << QByteArray("OFF\n20 1 0\n0 0 0\n1 0 0\n")
                                            << "the file ends inside vertex 2";
    QTest::newRow("binary OFF face of 2^31-1")
        << "big-binary.off"
        << QByteArray("OFF BINARY\n") + le32(3) + le32(1) + le32(0) + lef(0) + lef(0) + lef(0) + lef(1) + lef(0) + lef(0) +
               lef(0) + lef(1) + lef(0) + le32(0x7fffffff) + le32(0) + le32(1) + le32(2)
        << "more than the rest of the file holds";
    // 219-byte binary PLY files whose list count is 2^31-1 or -1 (took 100 s and 4.2 GB).
    QTest::newRow("binary PLY list of 2^31-1") << "big.ply" << plyBinaryTriangle(0x7fffffff)
                                               << "claims 2147483647 entries";
    QTest::newRow("binary PLY list of -1") << "negative.ply" << plyBinaryTriangle(-1) << "is -1, not a count";
    // Truncated: an ASCII list of 255 entries with a few given.
    QTest::newRow("ASCII PLY list cut short")
        << "short.ply"
        << QByteArray("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                      "255 0 1 2\n3 0 1 2\n")
        << "claims 255 entries";
    QTest::newRow("binary PLY vertices cut short")
        << "few.ply" << QByteArray(kPlyBinaryHeader).replace("vertex 3", "vertex 9") + QByteArray(20, '\0')
        << "the file ends inside vertex";
    // Found by fuzz_mesh: a count the header check read as 1 and the reader as -1 (it looped).
    QTest::newRow("PLY element count 1.0")
        << "fraction.ply" << QByteArray(kPlyBinaryHeader).replace("element vertex 3", "element junk 1.0\nelement vertex 3")
        << "is not a count the file can hold";
}

void TestHostileFiles::meshCountsBeyondTheFile() {
    QFETCH(QString, name);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    writeFile(dir.filePath(name), bytes);
    writeFile(dir.filePath("scene.json"), meshScene(name));
    VERIFY_REFUSED(QStringList({"info", "scene.json"}), dir.path(), expected);
}

void TestHostileFiles::objLinesGiveTheTrueReason_data() {
    QTest::addColumn<QByteArray>("vertex");
    QTest::addColumn<QString>("expected");
    QTest::newRow("nan") << QByteArray("v nan 0 0") << "nan is not a finite number";
    QTest::newRow("1e39") << QByteArray("v 1e39 0 0") << "1e39 lies beyond single-precision range";
    QTest::newRow("letters") << QByteArray("v a b c") << "\"a\" is not a number";
    QTest::newRow("two coordinates") << QByteArray("v 1 2") << "fewer than three coordinates";
    // Found by fuzz_mesh: a corner without its vertex index aborted OpenMesh on an assertion.
    QTest::newRow("corner without index") << QByteArray("f /1/1 2/2/1 3/3/1") << "face corner \"/1/1\" has no vertex index";
}

void TestHostileFiles::objLinesGiveTheTrueReason() {
    QFETCH(QByteArray, vertex);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    writeFile(dir.filePath("m.obj"), "v 0 0 0\nv 1 0 0\n" + vertex + "\nf 1 2 3\n");
    writeFile(dir.filePath("scene.json"), meshScene("m.obj"));
    VERIFY_REFUSED(QStringList({"info", "scene.json"}), dir.path(), "m.obj: line 3: ");
    const Run r = runLucerna({"info", "scene.json"}, dir.path());
    QVERIFY2(r.err.contains(expected.toUtf8()) && !r.err.contains("does not exist"), r.err.constData());
}

void TestHostileFiles::objCornerThatIsAComment() {
    // Six bytes that passed the old OBJ check and aborted the process (exit 134) on an assertion
    // in OpenMesh's reader: in info, render and import alike (issue 41).
    QTemporaryDir dir;
    writeFile(dir.filePath("m.obj"), "f # /5");
    writeFile(dir.filePath("scene.json"), meshScene("m.obj"));
    const char* const expected = "m.obj: line 1: the face has 0 corners before the comment \"# /5\", a face needs three or more";
    VERIFY_REFUSED(QStringList({"info", "scene.json"}), dir.path(), expected);
    VERIFY_REFUSED(QStringList({"render", "scene.json", "-o", "o.exr"}), dir.path(), expected);
    VERIFY_REFUSED(QStringList({"import", "m.obj", "-o", "o.json"}), dir.path(), expected);
    QCOMPARE(leftovers(dir.path(), {"m.obj", "scene.json"}), QStringList());
}

void TestHostileFiles::stlFanReadsInTime() {
    // 40000 triangles around one vertex, 2 MB: OpenMesh's reader took 21 s (quadratic).
    QByteArray stl(80, ' ');
    stl += le32(40000);
    for (int i = 0; i < 40000; ++i) {
        for (float v : {0.f, 0.f, 1.f, 0.f, 0.f, 0.f, float(i + 1), 0.f, 0.f, float(i + 1), 1.f, 0.f}) stl += lef(v);
        stl += QByteArray(2, '\0');
    }
    QTemporaryDir dir;
    writeFile(dir.filePath("fan.stl"), stl);
    writeFile(dir.filePath("scene.json"), meshScene("fan.stl"));
    const Run r = runLucerna({"info", "scene.json"}, dir.path());
    QVERIFY2(r.exitCode == 0 && r.cpuSeconds < 2.0 * kResourceScale, qPrintable(describe({"info", "scene.json"}, r)));
}

void TestHostileFiles::importRefusesOrWritesALoadableScene_data() {
    QTest::addColumn<QString>("model");
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("refusal");  // empty: the import must succeed
    const QByteArray tail = "v 1 0 0\nv 0 1 0\nf 1 2 3\n";
    // OBJ files are read by Lucerna's reader before Assimp sees them (model_import.cpp).
    QTest::newRow("OBJ vertex at 1e39") << "m.obj" << "v 1e39 0 0\n" + tail << "m.obj: line 1: vertex coordinate 1e39 lies beyond";
    QTest::newRow("OBJ vertex nan") << "m.obj" << "v nan 0 0\n" + tail << "m.obj: line 1: vertex coordinate nan is not a finite";
    QTest::newRow("OBJ corner that is a comment") << "m.obj" << QByteArray("f # /5") << "m.obj: line 1: the face has 0 corners";
    QTest::newRow("OBJ corner without its vertex") << "m.obj" << "v 0 0 0\n" + tail + "f /1 2 3\n"
                                                   << "m.obj: line 5: face corner \"/1\" has no vertex index";
    QTest::newRow("OBJ texture index beyond the file") << "m.obj" << "v 0 0 0\nvt 0 0\n" + tail + "f 1/1 2/1 3/7\n"
                                                       << "m.obj: line 6: a corner names texture coordinate 7";
    QTest::newRow("OBJ line element beyond the file") << "m.obj" << "v 0 0 0\n" + tail + "l 1 9\n" << "a corner names vertex 9";
    QTest::newRow("OBJ vertex 1e38") << "m.obj" << "v 1e38 0 0\n" + tail << "";
    QTest::newRow("OBJ plain") << "m.obj" << "v 0 0 0\n" + tail << "";
    // glTF: one triangle whose first vertex is NaN, in an embedded buffer.
    QByteArray buffer;
    for (float v : {std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) buffer += lef(v);
    for (quint16 i : {0, 1, 2}) buffer += QByteArray(reinterpret_cast<const char*>(&i), 2);
    buffer += QByteArray(2, '\0');
    const QByteArray gltf =
        R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "n"}],
        "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,)" +
        buffer.toBase64() + R"("}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
    QTest::newRow("glTF vertex nan") << "m.gltf" << gltf << "not a finite point";
}

void TestHostileFiles::importRefusesOrWritesALoadableScene() {
    QFETCH(QString, model);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, refusal);
    QTemporaryDir dir;
    writeFile(dir.filePath(model), bytes);
    const QStringList args{"import", model, "-o", "out.json"};
    if (!refusal.isEmpty()) {
        VERIFY_REFUSED(args, dir.path(), refusal);
        QCOMPARE(leftovers(dir.path(), {model}), QStringList());
        return;
    }
    const Run r = runLucerna(args, dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(describe(args, r)));
    const Run info = runLucerna({"info", "out.json"}, dir.path());
    QVERIFY2(info.exitCode == 0, qPrintable(describe({"info", "out.json"}, info)));
}

void TestHostileFiles::importToAFolderLeavesNothing() {
    QTemporaryDir dir;
    writeFile(dir.filePath("cube.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    QVERIFY(QDir(dir.path()).mkdir("target.json"));
    VERIFY_REFUSED(QStringList({"import", "cube.obj", "-o", "target.json"}), dir.path(), "target.json: is a folder");
    QCOMPARE(leftovers(dir.path(), {"cube.obj", "target.json"}), QStringList());
    QVERIFY(QDir(dir.filePath("target.json")).isEmpty());
    VERIFY_REFUSED(QStringList({"import", "cube.obj", "-o", "missing/out.json"}), dir.path(), "does not exist");
    QCOMPARE(leftovers(dir.path(), {"cube.obj", "target.json"}), QStringList());
}

// Assimp runs in a process of its own (core/mesh/model_import.h): the test hook makes that process
// abort, as an importer crashing on a malformed file would.
void TestHostileFiles::importerCrashIsOneLine() {
    QTemporaryDir dir;
    writeFile(dir.filePath("cube.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    qputenv("LUCERNA_TEST_CRASH_READING", "model-importer");
    const Run r = runLucerna({"import", "cube.obj", "-o", "out.json"}, dir.path());
    qunsetenv("LUCERNA_TEST_CRASH_READING");
    QVERIFY2(r.exitCode == 2 && isOnePrintableLine(r.err), qPrintable(describe({"import"}, r)));
    QVERIFY2(r.err.contains("cube.obj: the model importer (Assimp) crashed on this file (SIGABRT)"),
             qPrintable(describe({"import"}, r)));
    QCOMPARE(leftovers(dir.path(), {"cube.obj"}), QStringList());
    const Run fine = runLucerna({"import", "cube.obj", "-o", "out.json"}, dir.path());
    QVERIFY2(fine.exitCode == 0, qPrintable(describe({"import"}, fine)));
}

void TestHostileFiles::overflowingPhotometryNamesFileAndLine_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("expected");
    QTest::newRow("IES candela multiplier 1e308") << "x.ies" << iesWithMultiplier("1e308") << "x.ies: line 5: ";
    QTest::newRow("IES candela multiplier 1e37") << "x.ies" << iesWithMultiplier("1e37") << "x.ies: line 5: ";
    QTest::newRow("LDT conversion factor 1e308") << "x.ldt" << ldtWithConversionFactor("1e308") << "x.ldt: line 24: ";
}

void TestHostileFiles::overflowingPhotometryNamesFileAndLine() {
    QFETCH(QString, name);
    QFETCH(QString, text);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    writeFile(dir.filePath(name), text.toUtf8());
    writeFile(dir.filePath("scene.json"), luminaireScene(name));
    VERIFY_REFUSED(QStringList({"info", "scene.json"}), dir.path(), expected);
    VERIFY_REFUSED(QStringList({"info", "scene.json"}), dir.path(), "beyond single-precision range");
    VERIFY_REFUSED(QStringList({"render", "scene.json", "-o", "out.exr", "--spp", "1"}), dir.path(), expected);
    QCOMPARE(leftovers(dir.path(), {name, "scene.json"}), QStringList());
    // The same files with a sane factor load.
    writeFile(dir.filePath(name), text.replace("1e308", "1").replace("1e37", "1").toUtf8());
    const Run r = runLucerna({"info", "scene.json"}, dir.path());
    QVERIFY2(r.exitCode == 0, qPrintable(describe({"info", "scene.json"}, r)));
}

void TestHostileFiles::binaryBytesStayOutOfMessages() {
    QTemporaryDir dir;
    QByteArray junk("\x01\x02\x00\x1b[31m\xff\xfe\r\x7f", 12);
    QString ies = iesWithMultiplier("1");
    QByteArray bytes = ies.toUtf8();
    bytes.replace("1.0 1.0 10", "1.0 " + junk + " 10");
    writeFile(dir.filePath("x.ies"), bytes);
    writeFile(dir.filePath("scene.json"), luminaireScene("x.ies"));
    VERIFY_REFUSED(QStringList({"info", "scene.json"}), dir.path(), "x.ies: line 6: expected a number");
    QByteArray ldt = ldtWithConversionFactor("1").toUtf8();
    ldt.replace("\n20\n", "\n" + junk + QByteArray(200, 'x') + "\n");
    writeFile(dir.filePath("x.ldt"), ldt);
    writeFile(dir.filePath("scene.json"), luminaireScene("x.ldt"));
    VERIFY_REFUSED(QStringList({"info", "scene.json"}), dir.path(), "\\x01\\x02\\x00\\x1b[31m\\xff\\xfe");
    const Run r = runLucerna({"info", "scene.json"}, dir.path());
    QVERIFY2(r.err.size() < 400, r.err.constData());  // a long word is cut
}

void TestHostileFiles::nonRegularPathsAreRefusedAtOnce() {
    QTemporaryDir dir;
    const auto fifo = [&](const QString& name) { QCOMPARE(::mkfifo(dir.filePath(name).toLocal8Bit().constData(), 0600), 0); };
    const auto link = [&](const QString& target, const QString& name) {
        QVERIFY(QFile::link(target, dir.filePath(name)));
    };
    fifo("fifo.ies");
    link("/dev/zero", "zero.ies");
    fifo("fifo.ldt");
    fifo("fifo.ply");
    link("/dev/zero", "zero.obj");
    fifo("fifo.json");
    link("/dev/zero", "zero.json");
    fifo("fifo.exr");
    link("/dev/zero", "zero.exr");
    fifo("fifo.obj");
    writeFile(dir.filePath("lum-fifo.json"), luminaireScene("fifo.ies"));
    writeFile(dir.filePath("lum-zero.json"), luminaireScene("zero.ies"));
    writeFile(dir.filePath("lum-fifo-ldt.json"), luminaireScene("fifo.ldt"));
    writeFile(dir.filePath("mesh-fifo.json"), meshScene("fifo.ply"));
    writeFile(dir.filePath("mesh-zero.json"), meshScene("zero.obj"));
    writeFile(dir.filePath("lib.obj"), "mtllib fifo.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    fifo("fifo.mtl");
    // A library that is not there makes Assimp try the file's own name with .mtl.
    writeFile(dir.filePath("fifo-fallback.obj"), "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    fifo("fifo-fallback.mtl");
    writeFile(dir.filePath("mesh-lib.json"), meshScene("lib.obj"));
    // A glTF file's buffers are opened by Assimp too: a FIFO blocked the import forever.
    const QByteArray gltf = R"({"asset":{"version":"2.0"},"buffers":[{"uri":"BUFFER","byteLength":36}],
        "bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,
        "type":"VEC3","max":[1,1,0],"min":[0,0,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
    writeFile(dir.filePath("fifo-buffer.gltf"), QByteArray(gltf).replace("BUFFER", "fifo.bin"));
    writeFile(dir.filePath("zero-buffer.gltf"), QByteArray(gltf).replace("BUFFER", "zero.bin"));
    fifo("fifo.bin");
    link("/dev/zero", "zero.bin");
    const QString small = dir.filePath("small.exr");
    {
        // A real 2 x 2 EXR to compare the hostile ones with.
        const Run r = runLucerna({"render", QString(LUCERNA_SHARED_DIR) + "/scenes/cornell-box.json", "-o", small,
                                  "--backend", "path", "--spp", "1", "--width", "2", "--height", "2"},
                                 dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(describe({"render"}, r)));
    }
    VERIFY_REFUSED(QStringList({"info", "lum-fifo.json"}), dir.path(), "fifo.ies: not a regular file (a FIFO)");
    VERIFY_REFUSED(QStringList({"info", "lum-zero.json"}), dir.path(), "zero.ies: not a regular file (a character device)");
    VERIFY_REFUSED(QStringList({"info", "lum-fifo-ldt.json"}), dir.path(), "fifo.ldt: not a regular file");
    VERIFY_REFUSED(QStringList({"render", "lum-fifo.json", "-o", "o.exr"}), dir.path(), "not a regular file");
    VERIFY_REFUSED(QStringList({"info", "mesh-fifo.json"}), dir.path(), "fifo.ply: not a regular file");
    VERIFY_REFUSED(QStringList({"info", "mesh-zero.json"}), dir.path(), "zero.obj: not a regular file");
    // The mesh reader takes positions only and opens no library; Assimp (import) would block.
    const Run lib = runLucerna({"info", "mesh-lib.json"}, dir.path());
    QVERIFY2(lib.exitCode == 0, qPrintable(describe({"info", "mesh-lib.json"}, lib)));
    VERIFY_REFUSED(QStringList({"import", "lib.obj", "-o", "o.json"}), dir.path(),
                   "lib.obj: the file names fifo.mtl, which is a FIFO, not a regular file");
    VERIFY_REFUSED(QStringList({"import", "fifo-fallback.obj", "-o", "o.json"}), dir.path(),
                   "the file names fifo-fallback.mtl, which is a FIFO");
    VERIFY_REFUSED(QStringList({"import", "fifo-buffer.gltf", "-o", "o.json"}), dir.path(),
                   "fifo-buffer.gltf: the file names fifo.bin, which is a FIFO, not a regular file");
    VERIFY_REFUSED(QStringList({"import", "zero-buffer.gltf", "-o", "o.json"}), dir.path(),
                   "the file names zero.bin, which is a character device");
    VERIFY_REFUSED(QStringList({"info", "fifo.json"}), dir.path(), "fifo.json: cannot read the file: not a regular file");
    VERIFY_REFUSED(QStringList({"info", "zero.json"}), dir.path(), "zero.json: cannot read the file: not a regular file");
    VERIFY_REFUSED(QStringList({"render", "fifo.json", "-o", "o.exr"}), dir.path(), "not a regular file");
    VERIFY_REFUSED(QStringList({"compare", "fifo.exr", small}), dir.path(), "fifo.exr: cannot read: not a regular file");
    VERIFY_REFUSED(QStringList({"compare", small, "zero.exr"}), dir.path(), "zero.exr: cannot read: not a regular file");
    VERIFY_REFUSED(QStringList({"convert", "fifo.exr", "o.png"}), dir.path(), "not a regular file");
    VERIFY_REFUSED(QStringList({"import", "fifo.obj", "-o", "o.json"}), dir.path(), "fifo.obj: not a regular file");
    VERIFY_REFUSED(QStringList({"import", "zero.obj", "-o", "o.json"}), dir.path(), "zero.obj: not a regular file");
    QVERIFY(!QFile::exists(dir.filePath("o.exr")) && !QFile::exists(dir.filePath("o.png")) &&
            !QFile::exists(dir.filePath("o.json")) && !QFile::exists(dir.filePath("o-meshes")));
}

void TestHostileFiles::exrHeaderWithoutPixels_data() {
    QTest::addColumn<quint64>("offset");
    QTest::newRow("offset table of zeros") << quint64(0);
    QTest::newRow("offsets beyond the file") << (quint64(1) << 28);
    QTest::newRow("offsets at the end of the file") << quint64(0);  // set below, once the size is known
}

void TestHostileFiles::exrHeaderWithoutPixels() {
    QFETCH(quint64, offset);
    QTemporaryDir dir;
    // 16384 x 16384 float RGB (3.2 GB of pixels) claimed by a 130 KB file.
    QByteArray bytes = exrWithoutPixels(16384, 16384, offset);
    if (QByteArray(QTest::currentDataTag()).contains("at the end")) bytes = exrWithoutPixels(16384, 16384, quint64(bytes.size()));
    QVERIFY(bytes.size() < 200 * 1024);
    writeFile(dir.filePath("huge.exr"), bytes);
    writeFile(dir.filePath("also.exr"), bytes);
    VERIFY_REFUSED(QStringList({"compare", "huge.exr", "also.exr"}), dir.path(), "huge.exr: ");
    VERIFY_REFUSED(QStringList({"convert", "huge.exr", "out.png"}), dir.path(), "huge.exr: ");
    QVERIFY(!QFile::exists(dir.filePath("out.png")));
}

// Found by fuzz_exr: OpenEXR's InputFile allocates an attribute's declared size before reading
// it (1.9 GB and 6 s for a file of 700 bytes).
void TestHostileFiles::exrAttributeClaimingGigabytes() {
    QTemporaryDir dir;
    for (const char* type : {"string", "mystery"}) {  // the second: an attribute of unknown type
        const QByteArray attribute = QByteArray("comments") + '\0' + type + '\0' + le32(0x7fffffff) + "a few bytes";
        writeFile(dir.filePath("attr.exr"), exrWithoutPixels(4, 4, 0, attribute));
        VERIFY_REFUSED(QStringList({"compare", "attr.exr", "attr.exr"}), dir.path(),
                       "attr.exr: the header's attribute \"comments\" claims 2147483647 bytes");
    }
    // A channel list whose declared size is not its content's: InputFile follows the content
    // and reads what follows as other attributes (it found a 1.8 GB one that way).
    QByteArray bytes = exrWithoutPixels(4, 4, 0);
    const QByteArray declared = QByteArray("chlist") + '\0' + le32(55);
    QVERIFY(bytes.contains(declared));
    bytes.replace(declared, QByteArray("chlist") + '\0' + le32(37));
    writeFile(dir.filePath("chlist.exr"), bytes);
    VERIFY_REFUSED(QStringList({"compare", "chlist.exr", "chlist.exr"}), dir.path(),
                   "the header's attribute \"channels\" (chlist) is malformed");
}

void TestHostileFiles::staleTemporariesAreRemoved() {
    QTemporaryDir dir;
    // What a SIGKILL during the write of out.exr leaves behind, and what another writer of the
    // same target, still at work (holding its lock), has open.
    const QString stale = dir.filePath(".out.exr.Ab12Cd.part"), busy = dir.filePath(".out.exr.Zz98Yy.part");
    const QString other = dir.filePath(".other.exr.Ab12Cd.part");
    writeFile(stale, "half an EXR");
    writeFile(busy, "another writer's half");
    writeFile(other, "not this target's");
    const int fd = ::open(busy.toLocal8Bit().constData(), O_RDONLY);
    QVERIFY(fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) == 0);
    const Run r = runLucerna({"render", QString(LUCERNA_SHARED_DIR) + "/scenes/cornell-box.json", "-o", "out.exr",
                              "--backend", "path", "--spp", "1", "--width", "4", "--height", "4"},
                             dir.path());
    ::close(fd);
    QVERIFY2(r.exitCode == 0, qPrintable(describe({"render"}, r)));
    QVERIFY(QFile::exists(dir.filePath("out.exr")));
    QVERIFY(!QFile::exists(stale));
    QVERIFY(QFile::exists(busy));
    QVERIFY(QFile::exists(other));
}

void TestHostileFiles::badOutputPathIsRefusedBeforeRendering() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkdir("folder.exr"));
    const QString cornell = QString(LUCERNA_SHARED_DIR) + "/scenes/cornell-box.json";
    // 100000 spp would take minutes: a refusal under a second is one before the render.
    VERIFY_REFUSED(QStringList({"render", cornell, "-o", "missing_dir/x.exr", "--spp", "100000"}), dir.path(),
                   "missing_dir/x.exr: the folder missing_dir does not exist");
    VERIFY_REFUSED(QStringList({"render", cornell, "-o", "folder.exr", "--spp", "100000"}), dir.path(),
                   "folder.exr: is a folder");
    writeFile(dir.filePath("file"), "x");
    VERIFY_REFUSED(QStringList({"render", cornell, "-o", "file/x.exr", "--spp", "100000"}), dir.path(), "is not a folder");
    VERIFY_REFUSED(QStringList({"convert", QString(LUCERNA_SHARED_DIR) + "/scenes/cornell-box.ref.exr", "missing_dir/x.png"}),
                   dir.path(), "does not exist");
    VERIFY_REFUSED(QStringList({"grid", cornell, "--work-plane", "0.1", "--csv", "missing_dir/g.csv"}), dir.path(),
                   "does not exist");
    QCOMPARE(leftovers(dir.path(), {"folder.exr", "file"}), QStringList());
}

// SIGINT as soon as the process catches it (read from /proc), which is before it reads its
// scene: a 300,000-triangle mesh file still to load.
void TestHostileFiles::interruptBeforeTheSceneHasLoaded() {
    QTemporaryDir dir;
    QByteArray ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                     "property float z\nelement face 300000\nproperty list uchar int vertex_indices\nend_header\n";
    for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) ply += lef(v);
    const QByteArray face = QByteArray(1, '\3') + le32(0) + le32(1) + le32(2);
    ply.reserve(ply.size() + 300000 * face.size());
    for (int i = 0; i < 300000; ++i) ply += face;
    writeFile(dir.filePath("big.ply"), ply);
    writeFile(dir.filePath("scene.json"), meshScene("big.ply"));
    bool sent = false;
    const QString binary = QFileInfo(LUCERNA_BINARY).canonicalFilePath();
    const Run r = runLucerna({"render", "scene.json", "-o", "out.exr", "--spp", "100000"}, dir.path(), [&](pid_t pid) {
        const QString status = QString("/proc/%1/status").arg(pid), exe = QString("/proc/%1/exe").arg(pid);
        for (int i = 0; i < 5000 && !sent; ++i) {
            // Before exec the child is a copy of this test, with its handlers.
            if (QFileInfo(exe).canonicalFilePath() == binary)
                for (const QByteArray& line : readAll(status).split('\n'))
                    if (line.startsWith("SigCgt:") &&
                        (line.mid(7).trimmed().toULongLong(nullptr, 16) & (1ull << (SIGINT - 1)))) {
                        ::kill(pid, SIGINT);
                        sent = true;
                    }
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
    });
    QVERIFY(sent);
    QVERIFY2(r.exitCode == 130, qPrintable(describe({"render"}, r)));
    QCOMPARE(r.err, QByteArray("render interrupted; no file written\n"));
    QCOMPARE(leftovers(dir.path(), {"big.ply", "scene.json"}), QStringList());
}

QTEST_GUILESS_MAIN(TestHostileFiles)
#include "test_hostile_files.moc"
