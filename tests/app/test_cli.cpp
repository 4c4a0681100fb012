// The command line of SPEC.md section 2: exit codes, one-line errors, output files written whole
// or not at all, an interrupted render leaving nothing behind.

#include "core/image/exr_io.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "csv_table.h"

#include <array>
#include <cmath>
#include <csignal>

using namespace lucerna;
using lucerna::test::CsvTable;

namespace {
const QString kCornell = QString(LUCERNA_SHARED_DIR) + "/scenes/cornell-box.json";
const QString kReference = QString(LUCERNA_SHARED_DIR) + "/scenes/cornell-box.ref.exr";

struct Run {
    int exitCode = -1;
    QString out, err;
};

Run runLucerna(const QStringList& args, int timeoutMs = 120000) {
    QProcess p;
    p.start(LUCERNA_BINARY, args);
    p.waitForFinished(timeoutMs);
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
            p.readAllStandardError()};
}

bool isOneLine(const QString& s) { return s.trimmed().count('\n') == 0 && !s.trimmed().isEmpty(); }
}  // namespace

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void renderWritesExrWithMetadata();
    void renderBadUsage_data();
    void renderBadUsage();
    void badSceneIsOneLine();
    void badDaylightSceneIsOneLine_data();
    void badDaylightSceneIsOneLine();
    void compareMetrics();
    void compareErrors();
    void infoPrintsStatistics();
    void interruptedRenderLeavesNoFile_data();
    void interruptedRenderLeavesNoFile();
    void interruptedRenderSavesWhenAsked();
    void renderWritesPngByName();
    void benchWritesCsvAndPlot();
    void benchBadUsage();
    void benchTakesAuto();
};

void TestCli::renderWritesExrWithMetadata() {
    QTemporaryDir dir;
    const QString out = dir.filePath("cb.exr");
    const Run r = runLucerna({"render", kCornell, "-o", out, "--backend", "path", "--spp", "2", "--width", "40",
                           "--height", "30", "--seed", "5"});
    QCOMPARE(r.exitCode, 0);
    const Image img = readExr(out.toStdString());
    QCOMPARE(img.width, 40);
    QCOMPARE(img.height, 30);
    QCOMPARE(img.attributes.at("lucerna:backend"), std::string("path"));
    QCOMPARE(img.attributes.at("lucerna:spp"), std::string("2"));
    QCOMPARE(img.attributes.at("lucerna:seed"), std::string("5"));
    QVERIFY(img.attributes.count("lucerna:seconds"));
    QVERIFY(img.mean() > 0.01);
    // auto says what it chose and why.
    const Run a = runLucerna({"render", kCornell, "-o", dir.filePath("auto.exr"), "--spp", "1", "--width", "8",
                           "--height", "8"});
    QCOMPARE(a.exitCode, 0);
    QVERIFY(a.err.contains("auto: "));
}

void TestCli::renderBadUsage_data() {
    QTest::addColumn<QStringList>("args");
    QTest::newRow("no scene") << QStringList{"render"};
    QTest::newRow("no output") << QStringList{"render", kCornell};
    QTest::newRow("unknown backend") << QStringList{"render", kCornell, "-o", "x.exr", "--backend", "nope"};
    QTest::newRow("bad spp") << QStringList{"render", kCornell, "-o", "x.exr", "--spp", "ten"};
    QTest::newRow("zero spp") << QStringList{"render", kCornell, "-o", "x.exr", "--spp", "0"};
    QTest::newRow("negative time") << QStringList{"render", kCornell, "-o", "x.exr", "--time", "-1"};
    QTest::newRow("huge width") << QStringList{"render", kCornell, "-o", "x.exr", "--width", "20000"};
    QTest::newRow("unknown option") << QStringList{"render", kCornell, "-o", "x.exr", "--fast"};
    QTest::newRow("tiff output") << QStringList{"render", kCornell, "-o", "x.tiff"};
    QTest::newRow("no extension") << QStringList{"render", kCornell, "-o", "x"};
    QTest::newRow("layers in a png") << QStringList{"render", kCornell, "-o", "x.png", "--layers", "albedo"};
    QTest::newRow("missing value") << QStringList{"render", kCornell, "-o", "x.exr", "--seed"};
    QTest::newRow("missing scene") << QStringList{"render", "/nonexistent/scene.json", "-o", "x.exr"};
    QTest::newRow("bad path option") << QStringList{"render", kCornell, "-o", "x.exr", "--option", "max_depth=-3"};
    QTest::newRow("mistyped cmlt option")
        << QStringList{"render", kCornell, "-o", "x.exr", "--backend", "cmlt", "--option", "lens_step=3"};
    QTest::newRow("option no backend reads (auto)") << QStringList{"render", kCornell, "-o", "x.exr", "--option", "speed=2"};
}

void TestCli::renderBadUsage() {
    QFETCH(QStringList, args);
    QTemporaryDir dir;
    QProcess p;
    p.setWorkingDirectory(dir.path());
    p.start(LUCERNA_BINARY, args);
    QVERIFY(p.waitForFinished(60000));
    QCOMPARE(p.exitCode(), 2);
    const QString err = p.readAllStandardError();
    QVERIFY2(isOneLine(err), qPrintable(err));
    QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
}

void TestCli::badSceneIsOneLine() {
    QTemporaryDir dir;
    const QString bad = dir.filePath("bad.json");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"lucerna": 1, "camera": {"position": [0,0,0], "target": [0,0,0], "fov_y": 40, "resolution": [8,8]},
               "materials": {}, "objects": []})");
    f.close();
    for (const QStringList& args : {QStringList{"info", bad}, QStringList{"render", bad, "-o", dir.filePath("o.exr")}}) {
        const Run r = runLucerna(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(isOneLine(r.err), qPrintable(r.err));
        QVERIFY2(r.err.contains("bad.json") && r.err.contains("camera"), qPrintable(r.err));
    }
    QVERIFY(!QFile::exists(dir.filePath("o.exr")));
}

void TestCli::badDaylightSceneIsOneLine_data() {
    // SPEC.md section 5's rules that span keys, as `lucerna info` and `lucerna render` meet them.
    QTest::addColumn<QString>("daylight");
    QTest::addColumn<QString>("place");
    QTest::newRow("sun time without site")
        << R"("lights": [{"name": "sun", "type": "sun", "illuminance": 1000, "time": "2024-06-21T10:00"}])"
        << "lights[0].time";
    QTest::newRow("cie_general without sun") << R"("sky": {"model": "cie_general", "cie_type": 12, "zenith_luminance": 1})"
                                             << "sky.model";
    QTest::newRow("two suns") << R"("lights": [{"name": "a", "type": "sun", "illuminance": 1, "direction": [0, -1, 0]},
                                             {"name": "b", "type": "sun", "illuminance": 1, "direction": [0, -1, 0]}])"
                              << "lights[1]";
    QTest::newRow("bad date") << R"("lights": [{"name": "sun", "type": "sun", "illuminance": 1, "time": "2026-02-30T10:00"}],
                                  "site": {"latitude": 47, "longitude": 8, "utc_offset": 1})"
                              << "lights[0].time";
}

void TestCli::badDaylightSceneIsOneLine() {
    QFETCH(QString, daylight);
    QFETCH(QString, place);
    QTemporaryDir dir;
    const QString bad = dir.filePath("daylight.json");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"lucerna": 1, "camera": {"position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [8, 8]},
               "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
               "objects": [{"name": "floor", "material": "white", "mesh": {"quad": [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]}}],
               )" + daylight.toUtf8() + "}");
    f.close();
    for (const QStringList& args : {QStringList{"info", bad}, QStringList{"render", bad, "-o", dir.filePath("o.exr")}}) {
        const Run r = runLucerna(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(isOneLine(r.err), qPrintable(r.err));
        QVERIFY2(r.err.contains("daylight.json: " + place), qPrintable(r.err));
    }
    QVERIFY(!QFile::exists(dir.filePath("o.exr")));
}

void TestCli::compareMetrics() {
    const Run r = runLucerna({"compare", kReference, kReference});
    QCOMPARE(r.exitCode, 0);
    const QStringList lines = r.out.trimmed().split('\n');
    QCOMPARE(lines.size(), 5);
    QCOMPARE(lines[0], QString("rmse: 0"));
    QCOMPARE(lines[1], QString("relmse: 0"));
    QVERIFY(lines[2].startsWith("mean_test: 0.1199"));
    QCOMPARE(lines[2].mid(11), lines[3].mid(10));
    QCOMPARE(lines[4], QString("nonfinite: 0"));
}

void TestCli::compareErrors() {
    QTemporaryDir dir;
    // Different sizes.
    const QString small = dir.filePath("small.exr");
    writeExr(small.toStdString(), Image(4, 4));
    Run r = runLucerna({"compare", small, kReference});
    QCOMPARE(r.exitCode, 2);
    QVERIFY(isOneLine(r.err));
    // Unreadable and missing files.
    QCOMPARE(runLucerna({"compare", dir.filePath("missing.exr"), kReference}).exitCode, 2);
    QCOMPARE(runLucerna({"compare", kCornell, kReference}).exitCode, 2);
    // A file without a B channel.
    const QString rg = dir.filePath("rg.exr");
    {
        Imf::Header header(4, 4);
        std::vector<float> data(16, 0.5f);
        Imf::FrameBuffer fb;
        for (const char* c : {"R", "G"}) {
            header.channels().insert(c, Imf::Channel(Imf::FLOAT));
            fb.insert(c, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(data.data()), sizeof(float), 4 * sizeof(float)));
        }
        Imf::OutputFile file(rg.toStdString().c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(4);
    }
    r = runLucerna({"compare", rg, small});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("B"), qPrintable(r.err));
    QCOMPARE(runLucerna({"compare", small}).exitCode, 2);
}

void TestCli::infoPrintsStatistics() {
    const Run r = runLucerna({"info", kCornell});
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains("triangles: 32"));
    QVERIFY(r.out.contains("emitter triangles: 2"));
    QVERIFY(r.out.contains("needs: diffuse area-lights"));
    // The Cornell light: 130 x 105 mm of radiance (17, 12, 4): pi A Y(L) 683 = 366 lm.
    QVERIFY2(r.out.contains("light: emitter, 365.684 lm"), qPrintable(r.out));
    // A photometric bulb is reported with the flux it was given.
    QTemporaryDir dir;
    QFile f(dir.filePath("bulb.json"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"lucerna": 1, "camera": {"position": [0, 1, -3], "target": [0, 0, 0], "fov_y": 40, "resolution": [8, 8]},
      "materials": {"white": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]}},
      "objects": [{"name": "floor", "material": "white", "mesh": {"quad": [[-2,0,-2],[-2,0,2],[2,0,2],[2,0,-2]]}}],
      "lights": [{"name": "bulb", "type": "point", "position": [0, 2, 0], "lumens": 800, "temperature": 2700}]})");
    f.close();
    const Run b = runLucerna({"info", dir.filePath("bulb.json")});
    QCOMPARE(b.exitCode, 0);
    QVERIFY2(b.out.contains("bulb: point, 800 lm"), qPrintable(b.out));
}

void TestCli::interruptedRenderLeavesNoFile_data() {
    QTest::addColumn<int>("signal");
    QTest::newRow("SIGINT") << int(SIGINT);
    QTest::newRow("SIGTERM") << int(SIGTERM);
}

void TestCli::interruptedRenderLeavesNoFile() {
    QFETCH(int, signal);
    QTemporaryDir dir;
    const QString out = dir.filePath("long.exr");
    QProcess p;
    p.start(LUCERNA_BINARY, {"render", kCornell, "-o", out, "--time", "60"});
    QVERIFY(p.waitForStarted());
    QTest::qWait(1500);  // loading done, rendering under way
    QCOMPARE(p.state(), QProcess::Running);
    ::kill(pid_t(p.processId()), signal);
    QVERIFY(p.waitForFinished(10000));  // stops promptly, not after the budget
    QCOMPARE(p.exitCode(), 130);
    QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
}

// --save-on-interrupt: the first Ctrl-C ends the pass loop at the next pass boundary and the
// passes done are written (atomically, with their real spp); exit status 130 all the same.
void TestCli::interruptedRenderSavesWhenAsked() {
    QTemporaryDir dir;
    const QString out = dir.filePath("long.exr");
    QProcess p;
    p.start(LUCERNA_BINARY, {"render", kCornell, "-o", out, "--backend", "path", "--time", "60", "--width", "48",
                             "--height", "48", "--save-on-interrupt"});
    QVERIFY(p.waitForStarted());
    QTest::qWait(2000);  // loading done, passes under way
    QCOMPARE(p.state(), QProcess::Running);
    ::kill(pid_t(p.processId()), SIGINT);
    QVERIFY(p.waitForFinished(10000));  // at the next pass boundary, not after the budget
    const QString err = p.readAllStandardError();
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 130);
    QVERIFY2(err.contains("saving what converged so far"), qPrintable(err));
    // The file and nothing else: the temporary was renamed over it.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"long.exr"});
    const Image image = readExr(out.toStdString());
    QCOMPARE(image.width, 48);
    const double spp = std::stod(image.attributes.at("lucerna:spp"));
    const double seconds = std::stod(image.attributes.at("lucerna:seconds"));
    QVERIFY2(spp > 0, qPrintable(QString::number(spp)));
    QVERIFY2(seconds > 0 && seconds < 30, qPrintable(QString::number(seconds)));  // far short of the 60 s asked
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) sum += luminance(image.at(x, y));
    QVERIFY(std::isfinite(sum) && sum > 0);
}

// -o NAME.png writes the tone-mapped picture (as `convert` does), never an EXR under that name.
void TestCli::renderWritesPngByName() {
    QTemporaryDir dir;
    const QString png = dir.filePath("cb.PNG"), exr = dir.filePath("cb.exr"), converted = dir.filePath("conv.png");
    const QStringList common{"--backend", "path", "--spp", "2", "--width", "40", "--height", "30", "--seed", "3",
                             "--threads", "1"};
    const Run r = runLucerna(QStringList{"render", kCornell, "-o", png} + common);
    QCOMPARE(r.exitCode, 0);
    QFile f(png);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.read(8), QByteArray("\x89PNG\r\n\x1a\n", 8));
    f.close();
    const QImage picture(png, "PNG");
    QCOMPARE(picture.size(), QSize(40, 30));
    // The same picture as rendering an EXR and converting it.
    QCOMPARE(runLucerna(QStringList{"render", kCornell, "-o", exr} + common).exitCode, 0);
    QCOMPARE(runLucerna({"convert", exr, converted}).exitCode, 0);
    QCOMPARE(picture.convertToFormat(QImage::Format_RGB32), QImage(converted, "PNG").convertToFormat(QImage::Format_RGB32));
    // Another image type is refused in one line, before any work, and nothing is written.
    const Run tiff = runLucerna(QStringList{"render", kCornell, "-o", dir.filePath("cb.tiff")} + common);
    QCOMPARE(tiff.exitCode, 2);
    QVERIFY2(isOneLine(tiff.err) && tiff.err.contains("cb.tiff"), qPrintable(tiff.err));
    QVERIFY(!QFile::exists(dir.filePath("cb.tiff")));
}

// A reference of our own at a small size (so the budget buys many passes), then two backends for
// a second each: every row parses, the curves fall, and the plot names both.
// A path-traced Cornell box of size x size pixels at spp, seed 3: the benches' reference.
static bool renderReference(const QString& path, int spp, int size) {
    return runLucerna({"render", kCornell, "-o", path, "--backend", "path", "--spp", QString::number(spp), "--width",
                       QString::number(size), "--height", QString::number(size), "--seed", "3"})
               .exitCode == 0;
}

void TestCli::benchWritesCsvAndPlot() {
    QTemporaryDir dir;
    const QString ref = dir.filePath("ref.exr");
    QVERIFY(renderReference(ref, 512, 24));
    const QString out = dir.filePath("bench");
    const Run r = runLucerna({"bench", kCornell, "--reference", ref, "--backends", "path,mir:tries=2", "--time", "1",
                              "--start", "0.01", "--out", out, "--seed", "9"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const CsvTable csv = CsvTable::read(out + "/bench.csv");
    QCOMPARE(csv.header.join(','), QString("backend,seconds,spp,rmse,relmse,estimated_relmse,rays"));
    QMap<QString, QList<std::array<double, 3>>> curves;  // seconds, spp, relmse per backend
    QMap<QString, QList<double>> raysSeen;
    for (size_t row = 0; row < csv.rows.size(); ++row) {
        const QString line = csv.rows[row].join(',');
        QCOMPARE(csv.rows[row].size(), csv.header.size());
        std::array<double, 5> v{};
        const QString columns[] = {"seconds", "spp", "rmse", "relmse", "estimated_relmse"};
        for (size_t i = 0; i < v.size(); ++i) {
            const auto value = csv.number(row, columns[i]);
            // The film's own estimate needs both halves: "nan" before a second pass (a loaded
            // machine may reach the first sample time that early).
            if (columns[i] == "estimated_relmse" && csv.text(row, columns[i]) == "nan" && v[1] < 2) continue;
            QVERIFY2(value && std::isfinite(*value) && *value >= 0, qPrintable(line));
            v[i] = *value;
        }
        // Rays counted since the passes began: some by the first sample, more at each later one.
        const auto rays = csv.number(row, "rays");
        QVERIFY2(rays && *rays > 0, qPrintable(line));
        curves[csv.text(row, "backend")].append({v[0], v[1], v[3]});
        raysSeen[csv.text(row, "backend")].append(*rays);
    }
    QCOMPARE(curves.keys(), (QList<QString>{"mir:tries=2", "path"}));
    for (const auto& r : raysSeen)
        for (int i = 1; i < r.size(); ++i) QVERIFY(r[i] >= r[i - 1]);
    for (const auto& c : curves) {
        QVERIFY(c.size() >= 4);  // log-spaced from 0.01 s to 1 s
        for (int i = 1; i < c.size(); ++i) QVERIFY(c[i][0] > c[i - 1][0] && c[i][1] >= c[i - 1][1]);
        QVERIFY(c.last()[0] <= 1.5);
        QVERIFY2(c.last()[2] < 0.5 * c.first()[2], qPrintable(QString::number(c.first()[2]) + " -> " +
                                                             QString::number(c.last()[2])));
    }
    QFile svg(out + "/bench.svg");
    QVERIFY(svg.open(QIODevice::ReadOnly));
    const QString text = svg.readAll();
    QVERIFY(text.startsWith("<svg") && text.trimmed().endsWith("</svg>"));
    QCOMPARE(text.count("<polyline"), 4);  // two backends, relmse and rmse panels
    QVERIFY(text.contains(">mir:tries=2<") && text.contains(">path<") && text.contains("time (s)"));
}

void TestCli::benchTakesAuto() {
    // `auto` as a bench entry: the measured combination, its options any backend's; `auto-rule`:
    // the backend the rule auto was before it measured picks (said on stdout). Under auto's row,
    // what it measured and decided.
    QTemporaryDir dir;
    const QString ref = dir.filePath("ref.exr");
    QVERIFY(renderReference(ref, 64, 16));
    const QString out = dir.filePath("bench");
    const Run r = runLucerna({"bench", kCornell, "--reference", ref, "--backends", "auto:light_sampler=power,auto-rule",
                              "--time", "0.3", "--start", "0.05", "--out", out});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains("auto-rule: path: "), qPrintable(r.out));  // the Cornell box: path
    QVERIFY2(r.out.contains("  auto:light_sampler=power: measured path bdpt ir mir cmlt"), qPrintable(r.out));
    const CsvTable csv = CsvTable::read(out + "/bench.csv");
    QSet<QString> labels;
    for (size_t row = 0; row < csv.rows.size(); ++row) labels.insert(csv.text(row, "backend"));
    QCOMPARE(labels, (QSet<QString>{"auto:light_sampler=power", "auto-rule"}));
}

void TestCli::benchBadUsage() {
    QTemporaryDir dir;
    const QString small = dir.filePath("small.exr");
    writeExr(small.toStdString(), Image(4, 4));
    const QList<QStringList> cases = {
        {"bench", kCornell, "--backends", "path", "--time", "1"},                             // no reference
        {"bench", kCornell, "--reference", small, "--time", "1"},                             // no backends
        {"bench", kCornell, "--reference", small, "--backends", "path"},                      // no budget
        {"bench", kCornell, "--reference", small, "--backends", "path,nope", "--time", "1"},  // unknown backend
        {"bench", kCornell, "--reference", small, "--backends", "mir:tries", "--time", "1"},  // not name=value
        {"bench", kCornell, "--reference", dir.filePath("missing.exr"), "--backends", "path", "--time", "1"},
        {"bench", kCornell, "--reference", small, "--backends", "path", "--time", "1", "--width", "8", "--height", "8"},
        {"bench", kCornell, "--reference", small, "--backends", "mir:tries=0", "--time", "1"},  // bad option
        {"bench", kCornell, "--reference", small, "--backends", "path,mlt:lens_steps=2", "--time", "1"},  // cmlt's
        {"bench", kCornell, "--reference", small, "--backends", "path,mlt", "--option", "lens_steps=2", "--time", "1"},
    };
    for (const QStringList& args : cases) {
        const Run r = runLucerna(args);
        QVERIFY2(r.exitCode == 2, qPrintable(args.join(' ')));
        QVERIFY2(isOneLine(r.err), qPrintable(r.err));
    }
    QVERIFY(!QFile::exists("bench.csv"));
}

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
