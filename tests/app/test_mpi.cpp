// Distributed runs (issue 23): `mpirun -n N lucerna render|grid` against one process. The
// built lucerna runs under mpirun through QProcess (3 ranks, oversubscribed on a small machine),
// every run with a timeout so that a hang fails instead of waiting. Built only where lucerna is
// built with MPI.

#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"

#include <QDir>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include "csv_table.h"

#include <algorithm>
#include <cmath>
#include <csignal>

using namespace lucerna;
using lucerna::test::CsvTable;

namespace {

const QString kCornell = QString(LUCERNA_RESOURCE_DIR) + "/scenes/cornell-box.json";
// Small renders: 64 x 48 pixels, one thread a rank.
const QStringList kSmall = {"--width", "64", "--height", "48", "--threads", "1"};

struct Run {
    bool finished = false;  // within the timeout
    int exitCode = -1;
    QString out, err;
};

Run finish(QProcess& p, int timeoutMs) {
    Run r;
    r.finished = p.waitForFinished(timeoutMs);
    if (!r.finished) {
        p.kill();
        p.waitForFinished(5000);
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

// mpirun's arguments for `ranks` ranks: oversubscribed (more ranks than cores), allowed to run
// as root (containers), without the single-copy mechanism that containers forbid.
QStringList mpirunArgs(int ranks) {
    return {"--oversubscribe", "--allow-run-as-root", "--mca", "btl_vader_single_copy_mechanism", "none",
            "-x", "LUCERNA_TEST_ABORT_RANK", "-n", QString::number(ranks), LUCERNA_BINARY};
}

void startMpi(QProcess& p, int ranks, const QStringList& args) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    if (!env.contains("LUCERNA_TEST_ABORT_RANK")) env.insert("LUCERNA_TEST_ABORT_RANK", "");
    p.setProcessEnvironment(env);
    p.start(QStandardPaths::findExecutable("mpirun"), mpirunArgs(ranks) + args);
}

Run runMpi(int ranks, const QStringList& args, int timeoutMs = 60000) {
    QProcess p;
    startMpi(p, ranks, args);
    return finish(p, timeoutMs);
}

Run runAlone(const QStringList& args, int timeoutMs = 60000) {
    QProcess p;
    p.start(LUCERNA_BINARY, args);
    return finish(p, timeoutMs);
}

QString describe(const Run& r) { return QString("exit %1, stderr: %2").arg(r.exitCode).arg(r.err.right(600)); }

// The largest difference between two images' pixels and extra channels, relative to the value
// (and absolute below 1): the rounding of sums added in another order.
double largestDifference(const Image& a, const Image& b) {
    double worst = 0;
    const auto compare = [&](double x, double y) { worst = std::max(worst, std::abs(x - y) / std::max(1.0, std::abs(y))); };
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) compare(a.pixels[i][c], b.pixels[i][c]);
    for (const auto& [name, channel] : b.channels) {
        const auto it = a.channels.find(name);
        if (it == a.channels.end() || it->second.size() != channel.size()) return INFINITY;
        for (size_t i = 0; i < channel.size(); ++i) compare(it->second[i], channel[i]);
    }
    return worst;
}

bool bitIdentical(const Image& a, const Image& b) {
    if (a.pixels.size() != b.pixels.size() || a.channels.size() != b.channels.size()) return false;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (std::memcmp(&a.pixels[i][c], &b.pixels[i][c], sizeof(float)) != 0) return false;
    for (const auto& [name, channel] : a.channels)
        if (!b.channels.contains(name) ||
            std::memcmp(channel.data(), b.channels.at(name).data(), channel.size() * sizeof(float)) != 0)
            return false;
    return true;
}

}  // namespace

class TestMpi : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void pathTypeEqualsOneProcess_data();
    void pathTypeEqualsOneProcess();
    void metropolisHasTheWorkOfAllRanks_data();
    void metropolisHasTheWorkOfAllRanks();
    void sameSeedIsBitIdentical();
    void gridOnTwoRanksWithinErrorBars_data();
    void gridOnTwoRanksWithinErrorBars();
    void sceneErrorOnEveryRankIsOneLine();
    void deadRankLeavesNoFile();
    void interruptLeavesNoFile();
    void annualOnTwoRanksEqualsOneProcess();

private:
    QTemporaryDir dir_;
    Image reference_;  // the Cornell box at 64 x 48, path traced to 1024 spp
};

void TestMpi::initTestCase() {
    // Built only with MPI (tests/CMakeLists.txt), whose Debian packages bring mpirun.
    QVERIFY2(!QStandardPaths::findExecutable("mpirun").isEmpty(), "no mpirun on the PATH (Debian: openmpi-bin)");
    QVERIFY(dir_.isValid());
    const QString ref = dir_.filePath("reference.exr");
    const Run r = runAlone(QStringList{"render", kCornell, "-o", ref, "--backend", "path", "--spp", "1024", "--seed",
                                       "99", "--width", "64", "--height", "48", "--threads", "2"});
    QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
    reference_ = readExr(ref.toStdString());
}

// path, bdpt and ir deal out pass indices of one seed: 3 ranks make the one-process render's
// sums, added in another order. The per-light and illuminance layers pool alike.
void TestMpi::pathTypeEqualsOneProcess_data() {
    QTest::addColumn<QStringList>("options");
    QTest::newRow("path") << QStringList{"--backend", "path"};
    QTest::newRow("bdpt") << QStringList{"--backend", "bdpt"};
    QTest::newRow("ir") << QStringList{"--backend", "ir"};
    QTest::newRow("path with layers")
        << QStringList{"--backend", "path", "--layers", "lights,illuminance", "--illuminance-spp", "4"};
}

void TestMpi::pathTypeEqualsOneProcess() {
    QFETCH(QStringList, options);
    const QString one = dir_.filePath("one.exr"), three = dir_.filePath("three.exr");
    const QStringList common = QStringList{"--spp", "12", "--seed", "5"} + kSmall + options;
    const Run alone = runAlone(QStringList{"render", kCornell, "-o", one} + common);
    QVERIFY2(alone.exitCode == 0, qPrintable(describe(alone)));
    const Run shared = runMpi(3, QStringList{"render", kCornell, "-o", three} + common);
    QVERIFY2(shared.finished && shared.exitCode == 0, qPrintable(describe(shared)));
    const Image a = readExr(three.toStdString()), b = readExr(one.toStdString());
    QCOMPARE(a.attributes.at("lucerna:spp"), std::string("12"));  // the total over the ranks
    QCOMPARE(a.attributes.at("lucerna:ranks"), std::string("3"));
    QCOMPARE(a.attributes.at("lucerna:rank_passes"), std::string("4 4 4"));  // each rank its share
    QCOMPARE(a.attributes.at("lucerna:seed"), std::string("5"));
    QCOMPARE(a.channels.size(), b.channels.size());
    const double difference = largestDifference(a, b);
    QVERIFY2(difference < 1e-5, qPrintable(QString::number(difference)));
}

// mir, mlt and cmlt run chains of their own on each rank: 3 ranks of 8 passes each (24 in all)
// should have the mean of the scene and about the error of one process's 24 passes, well below
// that of one rank's 8 (fixed seeds: the runs are deterministic).
void TestMpi::metropolisHasTheWorkOfAllRanks_data() {
    QTest::addColumn<QString>("backend");
    QTest::newRow("mir") << "mir";
    QTest::newRow("mlt") << "mlt";
    QTest::newRow("cmlt") << "cmlt";
}

void TestMpi::metropolisHasTheWorkOfAllRanks() {
    QFETCH(QString, backend);
    const QStringList common = QStringList{"--backend", backend, "--seed", "1"} + kSmall;
    const QString all = dir_.filePath("all.exr"), share = dir_.filePath("share.exr"), three = dir_.filePath("three.exr");
    Run r = runAlone(QStringList{"render", kCornell, "-o", all, "--spp", "24"} + common);
    QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
    r = runAlone(QStringList{"render", kCornell, "-o", share, "--spp", "8"} + common);
    QVERIFY2(r.exitCode == 0, qPrintable(describe(r)));
    r = runMpi(3, QStringList{"render", kCornell, "-o", three, "--spp", "24"} + common);
    QVERIFY2(r.finished && r.exitCode == 0, qPrintable(describe(r)));
    const Image shared = readExr(three.toStdString());
    QCOMPARE(shared.attributes.at("lucerna:spp"), std::string("24"));
    QCOMPARE(shared.attributes.at("lucerna:rank_passes"), std::string("8 8 8"));
    const ImageMetrics mThree = compareImages(shared, reference_);
    const ImageMetrics mAll = compareImages(readExr(all.toStdString()), reference_);
    const ImageMetrics mShare = compareImages(readExr(share.toStdString()), reference_);
    const QString figures = QString("relmse: 3 ranks %1, one process 24 spp %2, 8 spp %3; mean %4 (reference %5)")
                                .arg(mThree.relmse).arg(mAll.relmse).arg(mShare.relmse).arg(mThree.meanTest)
                                .arg(mThree.meanRef);
    qInfo("%s: %s", qPrintable(backend), qPrintable(figures));
    QVERIFY2(std::abs(mThree.meanTest / mThree.meanRef - 1) < 0.06, qPrintable(figures));
    QVERIFY2(mThree.relmse < 0.7 * mShare.relmse, qPrintable(figures));
    QVERIFY2(mThree.relmse < 2.0 * mAll.relmse, qPrintable(figures));
}

// The pooled film is added in rank order whatever the timing: two runs are the same file's
// pixels, for a Metropolis backend (chains per rank) and a path-type one with layers.
void TestMpi::sameSeedIsBitIdentical() {
    for (const QStringList& options : {QStringList{"--backend", "mir", "--spp", "12"},
                                       QStringList{"--backend", "bdpt", "--spp", "6", "--layers", "lights"}}) {
        std::vector<Image> images;
        for (int run = 0; run < 2; ++run) {
            const QString out = dir_.filePath(QString("run%1.exr").arg(run));
            const Run r = runMpi(3, QStringList{"render", kCornell, "-o", out, "--seed", "7"} + kSmall + options);
            QVERIFY2(r.finished && r.exitCode == 0, qPrintable(describe(r)));
            images.push_back(readExr(out.toStdString()));
        }
        QVERIFY2(bitIdentical(images[0], images[1]), qPrintable(options.join(' ')));
    }
}

// A grid shared by 2 ranks (points for path, replicas for bdpt) against 1 process: every
// point within the two error bars; for path the same CSV, byte for byte (same samples, same stop).
void TestMpi::gridOnTwoRanksWithinErrorBars_data() {
    QTest::addColumn<QString>("method");
    QTest::addColumn<QString>("error");
    QTest::newRow("path (points)") << "path" << "0.05";
    QTest::newRow("bdpt (replicas)") << "bdpt" << "0.2";
}

void TestMpi::gridOnTwoRanksWithinErrorBars() {
    QFETCH(QString, method);
    QFETCH(QString, error);
    const QString one = dir_.filePath("one.csv"), two = dir_.filePath("two.csv");
    const QStringList common = {"grid", kCornell, "--work-plane", "0.5", "--border", "0", "--spacing", "0.1",
                                "--method", method, "--error", error, "--threads", "1", "--seed", "3"};
    const Run alone = runAlone(common + QStringList{"--csv", one});
    QVERIFY2(alone.exitCode == 0, qPrintable(describe(alone)));
    const Run shared = runMpi(2, common + QStringList{"--csv", two});
    QVERIFY2(shared.finished && shared.exitCode == 0, qPrintable(describe(shared)));
    QCOMPARE(shared.out.count("Eavg"), 1);  // rank 0 alone prints
    const CsvTable a = CsvTable::read(one), b = CsvTable::read(two);
    QCOMPARE(b.rows.size(), a.rows.size());
    QVERIFY(a.rows.size() == 36);
    for (size_t i = 0; i < a.rows.size(); ++i) {
        const double la = *a.number(i, "illuminance_lux"), lb = *b.number(i, "illuminance_lux");
        const double ea = *a.number(i, "error_lux"), eb = *b.number(i, "error_lux");
        QVERIFY2(std::abs(la - lb) <= ea + eb, qPrintable(QString("point %1: %2 +- %3 against %4 +- %5")
                                                              .arg(i).arg(lb).arg(eb).arg(la).arg(ea)));
    }
    if (method == "path") {  // points dealt out, each drawn as one process draws it
        const auto eavg = [](const QString& out) { return out.section("Eavg", 1, 1).section('\n', 0, 0); };
        QCOMPARE(eavg(shared.out), eavg(alone.out));
        QFile fa(one), fb(two);
        QVERIFY(fa.open(QIODevice::ReadOnly) && fb.open(QIODevice::ReadOnly));
        QCOMPARE(fb.readAll(), fa.readAll());  // the same passes, the same stop: the same CSV
    }
}

// Every rank loads the scene and fails alike: exit 2, rank 0's one line (mpirun adds its own
// box of lines, none starting "lucerna:"), no hang, no file.
void TestMpi::sceneErrorOnEveryRankIsOneLine() {
    const QString bad = dir_.filePath("bad.json"), out = dir_.filePath("bad.exr");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{\"camera\": ");
    f.close();
    const Run r = runMpi(3, {"render", bad, "-o", out, "--spp", "4"}, 30000);
    QVERIFY2(r.finished, "mpirun hung on a scene error");
    QCOMPARE(r.exitCode, 2);
    const QStringList ours = r.err.split('\n').filter(QRegularExpression("^lucerna:"));
    QVERIFY2(ours.size() == 1, qPrintable(r.err));
    QVERIFY2(ours[0].contains("bad.json"), qPrintable(ours[0]));
    QVERIFY(!QFile::exists(out));
}

// A rank that dies mid-render (the test's fault: rank 1 aborts after its first pass): mpirun
// ends the job, non-zero, and neither the EXR nor a temporary is left.
void TestMpi::deadRankLeavesNoFile() {
    QTemporaryDir empty;
    const QString out = empty.filePath("dead.exr");
    QProcess p;
    qputenv("LUCERNA_TEST_ABORT_RANK", "1");
    startMpi(p, 3, QStringList{"render", kCornell, "-o", out, "--backend", "path", "--spp", "300"} + kSmall);
    qunsetenv("LUCERNA_TEST_ABORT_RANK");
    const Run r = finish(p, 30000);
    QVERIFY2(r.finished, "mpirun hung after a rank died");
    QVERIFY2(r.exitCode != 0, qPrintable(describe(r)));
    QVERIFY2(r.err.contains("rank 1 aborts"), qPrintable(r.err));
    QVERIFY2(QDir(empty.path()).entryList(QDir::Files | QDir::Hidden).isEmpty(),
             qPrintable(QDir(empty.path()).entryList(QDir::Files | QDir::Hidden).join(' ')));
}

// Ctrl-C on mpirun (which passes it on as SIGTERM to every rank): all end, no file.
void TestMpi::interruptLeavesNoFile() {
    QTemporaryDir empty;
    const QString out = empty.filePath("long.exr");
    QProcess p;
    startMpi(p, 3, QStringList{"render", kCornell, "-o", out, "--backend", "path", "--time", "60"} + kSmall);
    QVERIFY(p.waitForStarted());
    QTest::qWait(3000);  // loaded, passes under way
    QCOMPARE(p.state(), QProcess::Running);
    ::kill(pid_t(p.processId()), SIGINT);
    const Run r = finish(p, 20000);
    QVERIFY2(r.finished, "mpirun did not end on SIGINT");
    QVERIFY2(r.exitCode != 0, qPrintable(describe(r)));
    QVERIFY2(QDir(empty.path()).entryList(QDir::Files | QDir::Hidden).isEmpty(),
             qPrintable(QDir(empty.path()).entryList(QDir::Files | QDir::Hidden).join(' ')));
}

// `mpirun -n 2 lucerna annual` (issue 39): the points dealt out, gathered on rank 0: the year's
// CSVs are those of one process, byte for byte (each point's paths depend on its index alone).
void TestMpi::annualOnTwoRanksEqualsOneProcess() {
    const QString office = QString(LUCERNA_RESOURCE_DIR) + "/scenes/daylit_office.json";
    const QString weather = QString(LUCERNA_RESOURCE_DIR) + "/weather/paris_synthetic.epw";
    const QStringList common{"annual", office, "--weather", weather, "--task-area", "Reference plane", "--spacing", "0.7",
                             "--paths", "1024", "--sun-paths", "32"};
    const QString one = dir_.filePath("annual1.csv"), two = dir_.filePath("annual2.csv");
    const QString oneHourly = dir_.filePath("annual1_h.csv"), twoHourly = dir_.filePath("annual2_h.csv");
    const Run alone = runAlone(common + QStringList{"--csv", one, "--hourly", oneHourly}, 120000);
    QVERIFY2(alone.exitCode == 0, qPrintable(describe(alone)));
    const Run shared = runMpi(2, common + QStringList{"--csv", two, "--hourly", twoHourly}, 180000);
    QVERIFY2(shared.exitCode == 0, qPrintable(describe(shared)));
    QVERIFY(shared.out.contains("sDA300/50%"));
    QCOMPARE(shared.out.count("sDA300/50%"), 1);  // rank 0 alone speaks
    const auto bytes = [](const QString& path) {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    };
    QVERIFY(!bytes(one).isEmpty());
    QCOMPARE(bytes(two), bytes(one));
    QCOMPARE(bytes(twoHourly), bytes(oneHourly));
}

QTEST_GUILESS_MAIN(TestMpi)
#include "test_mpi.moc"
