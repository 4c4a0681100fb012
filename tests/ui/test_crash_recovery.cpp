// No work lost to a reader that crashes: a child process (this executable, started again) opens a
// scene, edits it, and crashes as it starts to read a file (the test hook of
// core/read_crash_hook.h) in File > Import Mesh, Import Model, Open and Edit > Add Luminaire; the
// next start offers the recovery file, and it brings the edit back. Changes the designer let go
// (Discard) before the Open that crashed are not offered back.

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
// ("import-mesh", "import-model", "open", "luminaire"; "discard-open": Open after the designer
// answered Discard), which the hook makes crash. Returns only when it did not crash.
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
    else if (kind == "discard-open") {
        qputenv("LUCERNA_TEST_CRASH_READING", "open");
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        if (w.maybeSave()) w.openFile(file);  // as File > Open does
    }
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
    void discardedChangesAreNotOfferedBack();
    void importerCrashLeavesTheWindowStanding();

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

namespace {
// Runs the child on a copy of the Cornell box (`scene`), recovery files in `recovery`; true when
// it crashed as intended.
bool crashChild(const QString& kind, const QString& scene, const QString& recovery, const QString& file) {
    QFile::remove(scene);
    if (!QFile::copy(cornellPath(), scene)) return false;
    QFile::setPermissions(scene, QFile::ReadOwner | QFile::WriteOwner);
    QProcess child;
    child.setProcessChannelMode(QProcess::ForwardedErrorChannel);
    // No core dump of the intended crash.
    child.setChildProcessModifier([] {
        const rlimit none{0, 0};
        setrlimit(RLIMIT_CORE, &none);
    });
    child.start(QCoreApplication::applicationFilePath(), {kChild, kind, scene, recovery, file});
    return child.waitForFinished(kTimeout) && child.exitStatus() == QProcess::CrashExit;
}
}  // namespace

void TestCrashRecovery::crashWhileReadingLosesNoWork() {
    QFETCH(QString, kind);
    QFETCH(QString, file);
    const QString recovery = dir_.filePath("recovery-" + kind);
    const QString scene = dir_.filePath(kind + ".json");
    QVERIFY(crashChild(kind, scene, recovery, file));

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

void TestCrashRecovery::discardedChangesAreNotOfferedBack() {
    const QString recovery = dir_.filePath("recovery-discard");
    const QString scene = dir_.filePath("discard.json");
    QVERIFY(crashChild("discard-open", scene, recovery, cornellPath()));
    MainWindow w(scene);
    int asked = 0;
    w.setRecoveryQuestion([&] {
        ++asked;
        return QMessageBox::Yes;
    });
    QVERIFY(!w.startAutosave(recovery, kHour));
    QCOMPARE(asked, 0);
    QVERIFY(!w.document()->isModified());
}

// Assimp runs in a process of its own (core/mesh/model_import.h): when it crashes (the test hook
// aborts it), Import Model fails with the reason and the window and its edits stay as they were.
void TestCrashRecovery::importerCrashLeavesTheWindowStanding() {
    const QString model = dir_.filePath("triangle.obj");
    QFile f(model);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    f.close();
    MainWindow w(cornellPath());
    trigger(w, "actionAddPointLight");
    const Scene edited = w.document()->scene();
    qputenv("LUCERNA_TEST_CRASH_READING", "model-importer");
    const bool imported = w.importModelFile(model);
    qunsetenv("LUCERNA_TEST_CRASH_READING");
    QVERIFY(!imported);
    QVERIFY(w.lastError().contains("the model importer (Assimp) crashed on this file"));
    QCOMPARE(w.document()->scene().objects.size(), edited.objects.size());
    QCOMPARE(w.document()->scene().lights.size(), edited.lights.size());
    QVERIFY(w.importModelFile(model));  // the next import runs a fresh importer
    QCOMPARE(w.document()->scene().objects.size(), edited.objects.size() + 1);
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
