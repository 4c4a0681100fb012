// A grid's --method auto (render/photometry/grid_auto.h, issue 38): how a method's time to the
// target is projected, when a piloted method takes over from the running one, that a method far
// ahead does, and that a grid the first method finishes quickly is not held up by pilots (the
// last two through the command line).

#include "process_run.h"
#include "render/photometry/grid_auto.h"

#include <QRegularExpression>
#include <QTest>

#include <cmath>
#include <limits>
#include <string>

using namespace lucerna;

namespace {
// `lucerna grid SCENE ARGS` on a bundled scene: what it printed, or why it failed.
QString runGrid(const QString& scene, const QStringList& args) {
    const lucerna::test::Run r =
        lucerna::test::runLucerna(QStringList{"grid", QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/") + scene} + args, 60000);
    return r.exitCode == 0 ? r.out : "failed: " + r.err;
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

    // Seconds x (error / target)^2 for the passes, the preparation added unscaled; infinite
    // before the error bars are trusted.
    void projectsThePassesNotThePreparation() {
        GridSettings settings;
        settings.targetRelativeError = 0.03;
        settings.minPasses = 8;
        GridResult r;
        r.passes = 4;
        r.maxRelativeError = 0.06;  // twice the target: the passes need 4 times their time
        QCOMPARE(projectedGridSeconds(r, 2.0, GridMethod::Bdpt, settings), 8.0);
        r.prepareSeconds = 1.5;
        QCOMPARE(projectedGridSeconds(r, 2.0, GridMethod::Bdpt, settings), 1.5 + 0.5 * 4);
        r.prepareSeconds = 3;  // timed past `ran` (a pilot's clock): all of it preparation
        QCOMPARE(projectedGridSeconds(r, 2.0, GridMethod::Bdpt, settings), 2.0);
        r.prepareSeconds = 0;
        QVERIFY(std::isinf(projectedGridSeconds(r, 2.0, GridMethod::Path, settings)));  // 4 of 8 passes
        r.passes = 8;
        QCOMPARE(projectedGridSeconds(r, 2.0, GridMethod::Path, settings), 8.0);
        r.maxRelativeError = std::numeric_limits<double>::infinity();
        QVERIFY(std::isinf(projectedGridSeconds(r, 2.0, GridMethod::Path, settings)));
    }

    // The caustic scene's floor: ir, auto's first method, reaches 6% in about 7 s (its worst
    // point lies in the glass sphere's caustic), path in about 1.5 s. Path's pilot takes over
    // (17 of 17 seeds on a quiet machine, its projection 0.28 to 0.66 times ir's rest; 8 of 9
    // beside two other tests' renders) and the grid ends with path's passes at the target. Three
    // of five seeds must show it.
    void aMethodFarAheadTakesOver() {
        int tookOver = 0;
        QString outputs;
        for (const char* seed : {"1", "2", "3", "4", "5"}) {
            const QString out = runGrid("caustics.json", {"--work-plane", "0.01", "--method", "auto", "--error", "0.06",
                                                          "--time", "20", "--seed", seed});
            outputs += out;
            QVERIFY2(out.contains("auto: started with ir;"), qPrintable(out));
            tookOver += out.contains("method path (auto)") && out.contains("took over") &&
                        !out.contains("target not reached");
        }
        QVERIFY2(tookOver >= 3, qPrintable(outputs));
    }

    // The luminaire scene: ir reaches 3% in about 0.1 s. A pilot lasts at most 5% of ir's
    // projected rest and all pilots 10% of its total, so the grid costs what ir costs: on a quiet
    // machine nothing is piloted; under load (a longer projection) a 0.01 s path pilot may be.
    void aQuickGridIsNotHeldUp() {
        const QString out = runGrid("luminaire.json", {"--work-plane", "0.8", "--method", "auto", "--error", "0.03",
                                                       "--time", "20", "--seed", "4"});
        const QRegularExpressionMatch pilots = QRegularExpression("pilots took ([0-9.]+) s\n").match(out);
        QVERIFY2(out.contains("method ir (auto)") && out.contains("; ran ir;") && pilots.hasMatch() &&
                     std::stod(pilots.captured(1).toStdString()) <= 0.1,
                 qPrintable(out));
    }
};

QTEST_GUILESS_MAIN(TestGridAuto)
#include "test_grid_auto.moc"
