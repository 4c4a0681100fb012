// No work lost to a reader that crashes: a child process (this executable, started again) opens a
// scene, edits it, and crashes as it starts to read a file (the test hook of
// ui/io/read_crash_hook.h) in File > Import Mesh, Import Model, Open and Edit > Add Luminaire; the
// next start offers the recovery file, and it brings the edit back.

#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/resource.h>

using namespace lucerna;
using namespace lucerna::test;

namespace {
constexpr int kTimeout = 30000;  // ms; generous for a loaded machine, never a timing assertion
constexpr int kHour = 3600 * 1000;  // the autosave interval: only the read's own autosave writes
constexpr char kChild[] = "--edit-then-crash-reading";

// The child: `scene` opened, a point light added (unsaved), then the read of `file` as `kind`
// ("import-mesh", "import-model", "open", "luminaire"), which the hook makes crash. Returns only
// when it did not crash.
int editThenCrashReading(const QString& kind, const QString& scene, const QString& recovery, const QString& file) {
    useTestSettings("test_crash_recovery");
    MainWindow w(scene);
    w.startAutosave(recovery, kHour);
    trigger(w, "actionAddPointLight");
    const bool mesh = kind == "import-mesh", model = kind == "import-model";
    qputenv("LUCERNA_TEST_CRASH_READING", mesh || model ? "import" : kind.toUtf8());
    if (mesh) w.importMeshFile(file);
    else if (model) w.importModelFile(file);
    else if (kind == "open") w.openFile(file);
    else w.addLuminaireFile(file);
    return 0;
}
}  // namespace

class TestCrashRecovery : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void crashWhileReadingLosesNoWork_data();
    void crashWhileReadingLosesNoWork();

private:
    QTemporaryDir dir_;
};

void TestCrashRecovery::initTestCase() {
    useTestSettings("test_crash_recovery");
    QVERIFY(dir_.isValid());
}

void TestCrashRecovery::crashWhileReadingLosesNoWork_data() {
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("file");
    // The hook crashes before the file is read: any path does.
    QTest::newRow("import mesh") << "import-mesh" << dir_.filePath("table.obj");
    QTest::newRow("import model") << "import-model" << dir_.filePath("table.obj");
    QTest::newRow("open") << "open" << cornellPath();
    QTest::newRow("add luminaire") << "luminaire" << QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaires/downlight.ies");
}

void TestCrashRecovery::crashWhileReadingLosesNoWork() {
    QFETCH(QString, kind);
    QFETCH(QString, file);
    const QString recovery = dir_.filePath("recovery-" + kind);
    const QString scene = dir_.filePath(kind + ".json");
    QVERIFY(QFile::copy(cornellPath(), scene));
    QFile::setPermissions(scene, QFile::ReadOwner | QFile::WriteOwner);

    QProcess child;
    child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    // No core dump of the intended crash.
    child.setChildProcessModifier([] {
        const rlimit none{0, 0};
        setrlimit(RLIMIT_CORE, &none);
    });
    child.start(QCoreApplication::applicationFilePath(), {kChild, kind, scene, recovery, file});
    QVERIFY(child.waitForFinished(kTimeout));
    QCOMPARE(child.exitStatus(), QProcess::CrashExit);

    // The next start: the recovery is offered, and it holds the edit.
    MainWindow w(scene);
    const auto lightsOnFile = w.document()->scene().lights.size();
    int asked = 0;
    w.setRecoveryQuestion([&] {
        ++asked;
        return QMessageBox::Yes;
    });
    QVERIFY(w.startAutosave(recovery, kHour));
    QCOMPARE(asked, 1);
    QCOMPARE(w.document()->scene().lights.size(), lightsOnFile + 1);
    QCOMPARE(w.document()->path(), QFileInfo(scene).absoluteFilePath().toStdString());
    QVERIFY(w.document()->isModified());  // still unsaved work
    w.setSaveQuestion([] { return QMessageBox::Discard; });
    w.close();
}

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    if (argc == 6 && qstrcmp(argv[1], kChild) == 0)
        return editThenCrashReading(argv[2], argv[3], argv[4], argv[5]);
    TestCrashRecovery test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_crash_recovery.moc"
