// A render whose film cannot be allocated is bad input: one line, exit 2. Apart from the hostile
// files (test_hostile_files) because it cannot run under AddressSanitizer: it needs the child's
// 4 GB address-space limit (ASan reserves terabytes of shadow), and ASan ends the process on a
// failed allocation instead of throwing std::bad_alloc. CMake leaves it out of a LUCERNA_SANITIZE
// build.

#include "measured_run.h"

#include <QtTest>

using namespace lucerna::test;

class TestFilmMemory : public QObject {
    Q_OBJECT
private slots:
    void filmTooLargeForMemory();
};

// 16384 x 16384 needs a 12.9 GB film: refused in one line (exit 2), not std::bad_alloc (exit 1),
// whether the machine has that much memory or not (the address space here is 4 GB).
void TestFilmMemory::filmTooLargeForMemory() {
    QTemporaryDir dir;
    const QStringList args{"render", QString(LUCERNA_SHARED_DIR) + "/scenes/cornell-box.json", "-o", "out.exr",
                           "--backend", "path", "--spp", "1", "--width", "16384", "--height", "16384"};
    const Run r = runLucerna(args, dir.path());
    QVERIFY2(r.exitCode == 2 && isOnePrintableLine(r.err), qPrintable(describe(args, r)));
    QVERIFY2(r.err.contains("a 16384 x 16384 render needs more memory than is available"), qPrintable(describe(args, r)));
    QVERIFY2(r.cpuSeconds < 2.0 * kResourceScale && r.maxRssMb < 200 * kResourceScale, qPrintable(describe(args, r)));
    QCOMPARE(leftovers(dir.path(), {}), QStringList());
}

QTEST_GUILESS_MAIN(TestFilmMemory)
#include "test_film_memory.moc"
