// A grid's --method auto (render/photometry/grid_auto.h, issue 38): when a piloted method takes
// over from the running one, that a method far ahead does, and that a grid the first method
// finishes quickly is not held up by pilots. Through the command line.

#include "render/photometry/grid_auto.h"

#include <QProcess>
#include <QTest>

#include <limits>

using namespace lucerna;

namespace {
QString runGrid(const QString& scene, const QStringList& args) {
    QProcess p;
    p.start(LUCERNA_BINARY, QStringList{"grid", QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/") + scene} + args);
    if (!p.waitForFinished(60000) || p.exitCode() != 0) return "failed: " + QString::fromUtf8(p.readAllStandardError());
    return QString::fromUtf8(p.readAllStandardOutput());
}
}  // namespace

class TestGridAuto : public QObject {
    Q_OBJECT

private slots:
    // Its rest must be under 0.7 times the running one's, or, where neither finishes within the
    // time left, its variance at the limit (as 1 / time) under 0.7 times the running one's.
    void takesOverOnlyWhenClearlyFaster() {
        const double none = std::numeric_limits<double>::infinity();
        QVERIFY(challengerTakesOver({5, 0}, {20, 10}, none));       // 5 s against a rest of 10 s
        QVERIFY(challengerTakesOver({7.5, 1}, {20, 10}, none));     // its pilot's second counts
        QVERIFY(!challengerTakesOver({7.5, 0}, {20, 10}, none));    // 0.75 of the rest
        QVERIFY(!challengerTakesOver({none, 1}, {20, 10}, none));   // a pilot that measured nothing
        QVERIFY(!challengerTakesOver({0.2, 0.1}, {10, 10}, none));  // the running one is done
        QVERIFY(challengerTakesOver({6, 0}, {40, 10}, 8));          // only the challenger finishes within 8 s
        QVERIFY(!challengerTakesOver({20, 0}, {40, 10}, 8));        // neither: variances 20/8 against 40/18
        QVERIFY(challengerTakesOver({10, 0}, {40, 10}, 8));         // 10/8 = 1.25 against 0.7 x 40/18 = 1.56
        QVERIFY(challengerTakesOver({12, 2}, {40, 10}, 8));         // 12/10 = 1.2 against 1.56
    }

    // The caustic scene's floor: ir, auto's first method, reaches 6% in about 7 s (its worst
    // point lies in the glass sphere's caustic), path in about 1.5 s. Path's pilot takes over
    // (17 of 17 seeds in development, its projection 0.28 to 0.66 times ir's rest) and the grid
    // ends with path's passes at the target. Two of three seeds must show it.
    void aMethodFarAheadTakesOver() {
        int tookOver = 0;
        QString outputs;
        for (const char* seed : {"1", "2", "3"}) {
            const QString out = runGrid("caustics.json", {"--work-plane", "0.01", "--method", "auto", "--error", "0.06",
                                                          "--time", "20", "--seed", seed});
            outputs += out;
            QVERIFY2(out.contains("auto: started with ir;"), qPrintable(out));
            tookOver += out.contains("method path (auto)") && out.contains("took over") &&
                        !out.contains("target not reached");
        }
        QVERIFY2(tookOver >= 2, qPrintable(outputs));
    }

    // The luminaire scene: ir reaches 3% in about 0.1 s. Its rest is too short to share (a pilot
    // would be under 0.05 s), so nothing is piloted and the grid costs what ir costs.
    void aQuickGridIsNotHeldUp() {
        const QString out = runGrid("luminaire.json", {"--work-plane", "0.8", "--method", "auto", "--error", "0.03",
                                                       "--time", "20", "--seed", "4"});
        QVERIFY2(out.contains("method ir (auto)") &&
                     out.contains("auto: started with ir; not measured: path, bdpt, mir, mlt, cmlt; ran ir; pilots took 0.0 s"),
                 qPrintable(out));
    }
};

QTEST_GUILESS_MAIN(TestGridAuto)
#include "test_grid_auto.moc"
