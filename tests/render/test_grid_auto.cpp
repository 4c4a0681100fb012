// A grid's --method auto (render/photometry/grid_auto.h, issue 38): how a method's time to the
// target is projected, when a piloted method takes over from the running one, that a method far
// ahead does, and that a grid the first method finishes quickly is not held up by pilots (the
// last two through the command line); how its runs of path and ir are combined
// (grid_combination.h), on made-up results and against closed forms.

#include "closed_form_scenes.h"
#include "process_run.h"
#include "render/photometry/grid_auto.h"
#include "render/photometry/grid_combination.h"
#include "render/photometry/grid_statistics.h"
#include "render_helpers.h"

#include <QRegularExpression>
#include <QTest>

#include <cmath>
#include <numbers>
#include <limits>
#include <string>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// A result of `method`'s `passes` passes with these values and error bars.
GridResult partOf(GridMethod method, std::vector<double> lux, std::vector<double> errorLux, int passes) {
    GridResult r = emptyGridResult(lux.size());
    r.method = method;
    r.lux = std::move(lux);
    r.errorLux = std::move(errorLux);
    r.passes = passes;
    r.samplesPerPoint = passes;
    return r;
}

// The grid of `points` in `scene` by one method alone, with this seed and target.
GridResult gridOf(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal, GridMethod method,
                  uint64_t seed, double target) {
    GridSettings settings;
    settings.method = method;
    settings.seed = seed;
    settings.targetRelativeError = target;
    settings.timeLimitSeconds = 60;  // a guard: each takes well under a second
    TaskSystem tasks(0);
    GridResult result;
    auto job = tasks.submit([&](TaskContext& ctx) { result = computeGridIlluminance(scene, points, normal, settings, ctx); });
    job->wait();
    job->rethrowIfFailed();
    return result;
}

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

    // A pilot that lost runs on where it may yet take over: path's or ir's short first one within
    // 3 times the running method's rest; any other ahead of it, or within twice its rest while
    // still falling fast.
    void aPilotAheadRunsOn() {
        QVERIFY(pilotRunsOn(true, false, 25, 10));
        QVERIFY(!pilotRunsOn(true, false, 35, 10));
        QVERIFY(pilotRunsOn(false, false, 8, 10));    // ahead, within the take-over margin of 0.7
        QVERIFY(!pilotRunsOn(false, false, 12, 10));  // behind, its projection settled
        QVERIFY(pilotRunsOn(false, true, 15, 10));    // behind, but still falling fast
        QVERIFY(!pilotRunsOn(false, true, 25, 10));
    }

    // A share of the running method's rest, within the pilots' tenth of its total; path's or
    // ir's first pilot a hundredth (at least 0.01 s), up to half the rest against path or ir.
    void pilotsAreAShareOfTheRest() {
        QCOMPARE(pilotLengthSeconds(false, true, 10, 20, 0), 0.5);  // a twentieth
        QCOMPARE(pilotLengthSeconds(true, true, 10, 20, 0), 0.1);   // a hundredth
        QCOMPARE(pilotLengthSeconds(true, false, 10, 20, 0), 0.1);
        QCOMPARE(pilotLengthSeconds(false, true, 10, 20, 1.8), 0.2);  // 2 s for all pilots, 1.8 taken
        // A grid ir finishes in a tenth of a second (the closed room of albedo 0.5): path's first
        // pilot still gets the shortest length, 0.01 s, against ir; against bdpt, no pilot of
        // 0.01 s fits in a twentieth of the rest.
        QCOMPARE(pilotLengthSeconds(true, true, 0.12, 0.137, 0), 0.01);
        QVERIFY(pilotLengthSeconds(true, false, 0.12, 0.137, 0) < 0.01);
        QCOMPARE(pilotLengthSeconds(true, true, 0.015, 0.2, 0), 0.0075);  // never past half the rest
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

    // Per point: a method's runs pooled by their passes, the methods weighed by the inverse of
    // their variance (the error bar over its Student quantile), floored against the reference
    // method's; a method far from the reference method's value left out there; a run of too few
    // passes left out; an exact point kept exact.
    void combinesRunsPointByPoint() {
        GridSettings settings;
        settings.targetRelativeError = 0.03;
        const GridResult a = partOf(GridMethod::Path, {100, 50, 10}, {2, 1, 0}, 400);
        const GridResult b = partOf(GridMethod::Vpl, {103, 40, 12}, {4, 1, 1}, 100);
        const GridResult few = partOf(GridMethod::Vpl, {500, 500, 500}, {1, 1, 1}, kCombinedMinPasses - 1);
        const GridResult* parts[] = {&a, &b, &few};
        const GridResult c = combineGridResults(parts, settings);
        const double sa = 2 / studentT975(399), sb = 4 / studentT975(99);
        const double wa = 1 / (sa * sa), wb = 1 / (sb * sb);
        QVERIFY(std::abs(c.lux[0] - (wa * 100 + wb * 103) / (wa + wb)) < 1e-9);
        QVERIFY(std::abs(c.errorLux[0] - std::sqrt(wa * wa * 4 + wb * wb * 16) / (wa + wb)) < 1e-9);
        QVERIFY(c.errorLux[0] < 2);  // tighter than either run's
        QCOMPARE(c.lux[1], 50.0);    // 40 is 14 standard deviations from 50: ir left out
        QCOMPARE(c.errorLux[1], 1.0);
        QCOMPARE(c.lux[2], 10.0);  // a's exact value
        QCOMPARE(c.errorLux[2], 0.0);
        QCOMPARE(c.passes, 500);
        QCOMPARE(c.maxRelativeError, gridMaxRelativeError(c));
        // Two runs of one method: by their passes, whatever their bars.
        const GridResult p1 = partOf(GridMethod::Path, {100}, {1}, 100);
        const GridResult p2 = partOf(GridMethod::Path, {104}, {9}, 300);
        const GridResult* same[] = {&p1, &p2};
        QCOMPARE(combineGridResults(same, settings).lux[0], 103.0);
        const GridResult* alone[] = {&a, &few};
        QCOMPARE(combineGridResults(alone, settings).lux, a.lux);
        // ir's bars are twice path's but at the last point a tenth of them (a rare contribution
        // not met yet): its variance there is floored at a quarter of its median ratio, 4, to
        // path's, so the two weigh alike.
        const GridResult path = partOf(GridMethod::Path, {100, 100, 100, 100}, {1, 1, 1, 2}, 1000);
        const GridResult ir = partOf(GridMethod::Vpl, {100, 100, 100, 98}, {2, 2, 2, 0.2}, 1000);
        const GridResult* rare[] = {&path, &ir};
        const GridResult r = combineGridResults(rare, settings);
        QVERIFY(std::abs(r.lux[3] - 99) < 1e-9);
        QVERIFY(std::abs(r.errorLux[3] - 2 / std::sqrt(2.0)) < 1e-9);  // ir's bar floored at path's
        QVERIFY(std::abs(r.lux[0] - 100) < 1e-9 && std::abs(r.errorLux[0] - 2 / std::sqrt(5.0)) < 1e-9);
    }

    // Independent runs of path and ir, combined, against closed forms: under a square emitter
    // (Lambert's formula; 16 points) and at the centre of a closed sphere lit by a cap (pi times
    // the shell's radiance, all of it indirect light: ir's VPLs and path's bounces, the skewed
    // estimates whose error bars could bend inverse-variance weights toward low values). Each
    // point within twice its combined 95% bar, the bar within the tighter part's; the sphere's
    // mean over eight seed pairs within twice the standard error of that mean.
    void combinedRunsAgreeWithClosedForms() {
        RectangleOverPlane plane;
        const RenderScene floor(sceneFromJson(plane.json()), 8, 8);
        std::vector<V3d> points;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) points.push_back(V3d(-0.75 + 0.5 * i, 0, -0.75 + 0.5 * j));
        GridSettings settings;
        settings.targetRelativeError = 0.03;
        const GridResult p = gridOf(floor, points, V3d(0, 1, 0), GridMethod::Path, 1, 0.03);
        const GridResult v = gridOf(floor, points, V3d(0, 1, 0), GridMethod::Vpl, 2, 0.03);
        const GridResult* both[] = {&p, &v};
        const GridResult c = combineGridResults(both, settings);
        for (size_t i = 0; i < points.size(); ++i) {
            const double expected = 683.0 * plane.radiance * lambertPolygonIrradiance(points[i], V3d(0, 1, 0), plane.emitter());
            QVERIFY2(std::abs(c.lux[i] - expected) <= 2 * c.errorLux[i] &&
                         c.errorLux[i] <= 1.01 * std::min(p.errorLux[i], v.errorLux[i]),
                     qPrintable(QString("point %1: %2 +- %3 lx (path %4 +- %5, ir %6 +- %7), expected %8")
                                    .arg(i).arg(c.lux[i]).arg(c.errorLux[i]).arg(p.lux[i]).arg(p.errorLux[i])
                                    .arg(v.lux[i]).arg(v.errorLux[i]).arg(expected)));
        }
        SphereWithEmittingCap sphere;
        sphere.rings = 24;
        sphere.segments = 48;
        const RenderScene inside(sceneFromJson(sphere.json()), 8, 8);
        const double expected = 683.0 * std::numbers::pi * sphere.expectedRadiance();
        double sum = 0, sumSquares = 0;
        const int seeds = 8;
        for (int k = 0; k < seeds; ++k) {
            const GridResult ps = gridOf(inside, {V3d(0, 0, 0)}, V3d(0, -1, 0), GridMethod::Path, 10 + 2 * k, 0.05);
            const GridResult vs = gridOf(inside, {V3d(0, 0, 0)}, V3d(0, -1, 0), GridMethod::Vpl, 11 + 2 * k, 0.05);
            const GridResult* pair[] = {&ps, &vs};
            const GridResult cs = combineGridResults(pair, settings);
            QVERIFY2(std::abs(cs.lux[0] - expected) <= 2 * cs.errorLux[0],
                     qPrintable(QString("seed pair %1: %2 +- %3 lx, expected %4").arg(k).arg(cs.lux[0]).arg(cs.errorLux[0]).arg(expected)));
            sum += cs.lux[0];
            sumSquares += cs.lux[0] * cs.lux[0];
        }
        const double mean = sum / seeds;
        const double standardError = std::sqrt((sumSquares / seeds - mean * mean) / (seeds - 1));
        QVERIFY2(std::abs(mean - expected) <= 4 * standardError,
                 qPrintable(QString("mean %1 lx (standard error %2), expected %3").arg(mean).arg(standardError).arg(expected)));
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
        QVERIFY2(out.contains("method ir (auto)") && out.contains("; ran ir") && pilots.hasMatch() &&
                     std::stod(pilots.captured(1).toStdString()) <= 0.1,
                 qPrintable(out));
    }
};

QTEST_GUILESS_MAIN(TestGridAuto)
#include "test_grid_auto.moc"
