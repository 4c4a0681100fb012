// Calculation grids (issue 7): EN 12464-1's layout and figures, and the illuminance of each
// point against closed forms: a delta light over a floor (E = I cos / r^2, exact for both
// estimators), a rectangular emitter (Lambert's formula, within the error bar), and the inside
// of a closed sphere (indirect light only, uniform), for the path and the VPL estimators.

#include "closed_form_scenes.h"
#include "daylight_scenes.h"
#include "core/photometry/calculation_grid.h"
#include "core/image/exr_io.h"
#include "csv_table.h"
#include "render/photometry/grid_calculation.h"
#include "render/photometry/grid_statistics.h"
#include "render/photometry/grid_text.h"
#include "core/number_format.h"
#include "render/photometry/illuminance_layer.h"
#include "render_helpers.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>

using namespace lucerna;
using namespace lucerna::test;

namespace {

GridResult computeGrid(const SceneSnapshot& scene, const std::vector<V3d>& points, const V3d& normal,
                       const GridSettings& settings) {
    const RenderScene renderScene(scene, 8, 8);
    TaskSystem tasks(0);
    GridResult result;
    auto job = tasks.submit(
        [&](TaskContext& ctx) { result = computeGridIlluminance(renderScene, points, normal, settings, ctx); });
    job->wait();
    job->rethrowIfFailed();
    return result;
}

// A horizontal square grid facing up, centred on the y axis at height y, `side` across (scene
// units), its points `spacing` metres apart.
CalculationGrid squareGrid(double y, double side, double spacing) {
    CalculationGrid g;
    g.corner = V3d(-0.5 * side, y, 0.5 * side);
    g.edgeU = V3d(side, 0, 0);
    g.edgeV = V3d(0, 0, -side);
    g.spacingMeters = spacing;
    return g;
}

// 4 x 4 points on the floor of RectangleOverPlane (y = 0, facing up), 2 m across under its emitter.
CalculationGrid floorUnderTheEmitter() { return squareGrid(0, 2, 0.5); }

// Within twice the 95% error bar (fails about once in a million runs, not once in twenty) for
// an unbiased method; within `bias` of the expected value for the preview. The Metropolis methods
// (mir, mlt, cmlt) pass also within the requested target: in the short runs a 3% target takes,
// their replicas' spread understates the error of points that are far below the target (seen
// once in about ten full test runs: mlt 509.0 +- 4.5 lx against 520.2, -2.2%; the rounds stop when
// the spread happens to be small, and a short chain's estimate is skewed), so for them the
// promise tested is the grid's own, the target, wherever the bar is tighter than it.
bool agrees(const GridResult& r, size_t i, double expected, double bias, GridMethod method, double target) {
    if (bias > 0) return std::abs(r.lux[i] / expected - 1) <= bias;
    const bool metropolis = method == GridMethod::Mir || method == GridMethod::Mlt || method == GridMethod::Cmlt;
    if (metropolis && std::abs(r.lux[i] / expected - 1) <= target) return true;
    return std::abs(r.lux[i] - expected) <= 2 * r.errorLux[i];
}

GridSettings settingsFor(GridMethod method, double target) {
    GridSettings s;
    s.method = method;
    s.targetRelativeError = target;
    // A guard against a run that never converges, not a budget: path and bdpt reach these targets
    // in well under a second, mlt takes about 12 s on an idle 2-core machine (and twice that
    // under load, where a 20 s guard failed the test).
    s.timeLimitSeconds = 120;
    return s;
}

}  // namespace

class TestGrid : public QObject {
    Q_OBJECT
private slots:
    void en12464Spacing_data() {
        QTest::addColumn<double>("d");
        QTest::addColumn<double>("p");
        QTest::newRow("1 m") << 1.0 << 0.2;
        QTest::newRow("10 m") << 10.0 << 1.0;
        QTest::newRow("100 m") << 100.0 << 5.0;
        QTest::newRow("capped") << 1e4 << 10.0;
    }
    void en12464Spacing() {
        QFETCH(double, d);
        QFETCH(double, p);
        QVERIFY(std::abs(lucerna::en12464Spacing(d) - p) < 1e-12);
    }

    void layoutFollowsTheSpacingRule() {
        CalculationGrid g;
        g.corner = V3d(1, 0.8, 2);
        g.edgeU = V3d(5000, 0, 0);  // millimetres: 5 m by 2 m
        g.edgeV = V3d(0, 0, -2000);
        const GridLayout l = layoutGrid(g, 0.001);
        const double p = 0.2 * std::pow(5.0, std::log10(5.0));  // 0.617 m
        QCOMPARE(l.nu, int(std::ceil(5.0 / p)));
        QCOMPARE(l.nv, int(std::ceil(2.0 / p)));
        QVERIFY(l.spacingUMeters <= p && l.spacingVMeters <= p);
        QCOMPARE(int(l.points.size()), l.nu * l.nv);
        // Cell centres: the first point half a cell in from the corner, the last half a cell from
        // the far corner.
        QVERIFY((l.points.front() - V3d(1 + 2500.0 / l.nu, 0.8, 2 - 1000.0 / l.nv)).length() < 1e-9);
        QVERIFY((l.points.back() - V3d(1 + 5000 - 2500.0 / l.nu, 0.8, 2 - 2000 + 1000.0 / l.nv)).length() < 1e-9);
        QVERIFY((g.normal() - V3d(0, 1, 0)).length() < 1e-12);

        g.spacingMeters = 0.5;
        const GridLayout fixed = layoutGrid(g, 0.001);
        QCOMPARE(fixed.nu, 10);
        QCOMPARE(fixed.nv, 4);
    }

    // Two corners on a floor give a horizontal grid lifted by the offset and facing up; on a wall
    // (x = 0, facing +x) a vertical one on the wall, u to the viewer's right, facing the viewer.
    void gridFromTwoCorners() {
        const CalculationGrid floor = gridFromCorners(V3d(3, 0, 1), V3d(0, 1, 0), V3d(1, 0, 4), 1.0, 0.8);
        QVERIFY((floor.corner - V3d(1, 0.8, 4)).length() < 1e-12);
        QVERIFY((floor.edgeU - V3d(2, 0, 0)).length() < 1e-12);
        QVERIFY((floor.edgeV - V3d(0, 0, -3)).length() < 1e-12);
        QVERIFY((floor.normal() - V3d(0, 1, 0)).length() < 1e-12);
        const CalculationGrid wall = gridFromCorners(V3d(0, 1, 2), V3d(1, 0, 0), V3d(0, 2.5, 5), 0.001, 0.0);
        QVERIFY((wall.corner - V3d(0, 1, 5)).length() < 1e-12);  // from x = 0 looking at -x, +z is left
        QVERIFY((wall.edgeU - V3d(0, 0, -3)).length() < 1e-12);
        QVERIFY((wall.edgeV - V3d(0, 1.5, 0)).length() < 1e-12);
        QVERIFY((wall.normal() - V3d(1, 0, 0)).length() < 1e-12);
        const CalculationGrid ceiling = gridFromCorners(V3d(0, 3, 0), V3d(0, -1, 0), V3d(2, 3, 1), 1.0, 0.5);
        QVERIFY((ceiling.normal() - V3d(0, -1, 0)).length() < 1e-12);
        QVERIFY(std::abs(ceiling.corner.y - 2.5) < 1e-12);
    }

    void badGridsAreRejected() {
        CalculationGrid g;
        g.edgeV = V3d(0.5, 0, 1);  // not perpendicular to u
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, layoutGrid(g, 1.0));
        g.edgeV = V3d(0, 0, 0);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, layoutGrid(g, 1.0));
        g.edgeV = V3d(0, 0, 1);
        g.spacingMeters = 1e-4;  // 10^8 points
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, layoutGrid(g, 1.0));
    }

    void statistics() {
        const GridStatistics s = gridStatistics({100, 200, 300, 400});
        QCOMPARE(s.average, 250.0);
        QCOMPARE(s.minimum, 100.0);
        QCOMPARE(s.maximum, 400.0);
        QCOMPARE(s.uniformity, 0.4);
    }

    // A point light 1 m over a floor in a millimetre scene: E = I cos / (d mpu)^2 at every point.
    // Both estimators are exact here (the floor sees nothing but the light), so the tolerance is
    // float rounding.
    // Every method: path and ir by their estimators to 1%, the others (rendering the points as
    // irradiance sensors, slower per point) to 3%. The preview converges to its own answer
    // (clamped VPLs, shadow maps): it is held to `bias` of the closed form instead of its error bar.
    void pointLightIsExact_data() {
        QTest::addColumn<int>("method");
        QTest::addColumn<double>("target");
        QTest::addColumn<double>("bias");
        for (GridMethod m : kGridMethods)
            QTest::newRow(gridMethodName(m)) << int(m) << (m == GridMethod::Path || m == GridMethod::Vpl ? 0.01 : 0.03)
                                             << (m == GridMethod::Preview ? 0.03 : 0.0);
    }
    void pointLightIsExact() {
        QFETCH(int, method);
        QFETCH(double, target);
        DeltaLightOverPlane s;
        const SceneSnapshot scene = sceneFromJson(s.json());
        const CalculationGrid g = squareGrid(0, 3000, 0.5);  // millimetres
        const GridLayout layout = layoutGrid(g, 0.001);
        const GridResult r = computeGrid(scene, layout.points, g.normal(), settingsFor(GridMethod(method), target));
        QVERIFY(r.converged);
        for (size_t i = 0; i < layout.points.size(); ++i) {
            const V3d d = V3d(0, s.h, 0) - layout.points[i];
            const double r2 = d.length2() * 1e-6;  // m^2
            const double expected = 683.0 * s.intensity * (s.h / d.length()) / r2;
            QVERIFY2(std::abs(r.lux[i] / expected - 1) < 1e-4,
                     qPrintable(QString("point %1: %2 lx, expected %3").arg(i).arg(r.lux[i]).arg(expected)));
        }
    }

    // Under a square emitter: Lambert's formula, within the error bar (95%; checked at 2x so that
    // the test fails about once in a million runs, not once in twenty).
    void rectangularEmitterMatchesLambert_data() { pointLightIsExact_data(); }
    void rectangularEmitterMatchesLambert() {
        QFETCH(int, method);
        QFETCH(double, target);
        QFETCH(double, bias);
        RectangleOverPlane s;
        const SceneSnapshot scene = sceneFromJson(s.json());
        const CalculationGrid g = floorUnderTheEmitter();
        const GridLayout layout = layoutGrid(g, 1.0);
        const GridResult r = computeGrid(scene, layout.points, g.normal(), settingsFor(GridMethod(method), target));
        QVERIFY(r.converged);
        for (size_t i = 0; i < layout.points.size(); ++i) {
            const double expected =
                683.0 * s.radiance * lambertPolygonIrradiance(layout.points[i], V3d(0, 1, 0), s.emitter());
            QVERIFY2(agrees(r, i, expected, bias, GridMethod(method), target) && r.errorLux[i] <= 1.01 * target * r.lux[i],
                     qPrintable(QString("point %1: %2 +- %3 lx, expected %4").arg(i).arg(r.lux[i]).arg(r.errorLux[i]).arg(expected)));
        }
    }

    // Area and delta lights together: the delta lights are summed exactly and left out of the
    // light choice, so the area light's share must still come out whole (Lambert + I cos / r^2).
    void areaAndDeltaLightsTogether_data() { pointLightIsExact_data(); }
    void areaAndDeltaLightsTogether() {
        QFETCH(int, method);
        QFETCH(double, target);
        QFETCH(double, bias);
        RectangleOverPlane s;
        std::string json = s.json();
        json.insert(json.size() - 1, R"(, "lights": [{"name": "bulb", "type": "point", "position": [0.3, 0.6, -0.2], "intensity": [0.5, 0.5, 0.5]}])");
        const SceneSnapshot scene = sceneFromJson(json);
        const CalculationGrid g = floorUnderTheEmitter();
        const GridLayout layout = layoutGrid(g, 1.0);
        const GridResult r = computeGrid(scene, layout.points, g.normal(), settingsFor(GridMethod(method), target));
        QVERIFY(r.converged);
        for (size_t i = 0; i < layout.points.size(); ++i) {
            const V3d d = V3d(0.3, 0.6, -0.2) - layout.points[i];  // below the emitter: nothing between
            const double point = 0.5 * (d.y / d.length()) / d.length2();
            const double expected =
                683.0 * (s.radiance * lambertPolygonIrradiance(layout.points[i], V3d(0, 1, 0), s.emitter()) + point);
            QVERIFY2(agrees(r, i, expected, bias, GridMethod(method), target),
                     qPrintable(QString("point %1: %2 +- %3 lx, expected %4").arg(i).arg(r.lux[i]).arg(r.errorLux[i]).arg(expected)));
        }
    }

    // The centre of a closed sphere with an emitting cap, facing away from the cap: only the
    // shell is seen, whose radiance is uniform, so E = pi L_shell: all of it is indirect light,
    // the VPLs' part for the ir estimator.
    void sphereInteriorIsPiTimesShellRadiance_data() { pointLightIsExact_data(); }
    void sphereInteriorIsPiTimesShellRadiance() {
        QFETCH(int, method);
        QFETCH(double, target);
        QFETCH(double, bias);
        SphereWithEmittingCap s;
        s.rings = 24;
        s.segments = 48;
        const SceneSnapshot scene = sceneFromJson(s.json());
        const GridResult r = computeGrid(scene, {V3d(0, 0, 0)}, V3d(0, -1, 0), settingsFor(GridMethod(method), target));
        QVERIFY(r.converged);
        const double expected = 683.0 * std::numbers::pi * s.expectedRadiance();
        QVERIFY2(agrees(r, 0, expected, bias, GridMethod(method), target),
                 qPrintable(QString("%1 +- %2 lx, expected %3").arg(r.lux[0]).arg(r.errorLux[0]).arg(expected)));
    }

    // A sun's disc (0.53 degrees, 40 degrees from the zenith) over an open floor, the points 0.8 m
    // above it facing up: E = E_n cos Z, all of it straight from the disc. About one cosine-
    // distributed ray in 60 000 meets the disc (cos Z Omega / pi), so the methods that render the
    // points as sensors must find it by next-event estimation at the point (sensor_direct.h):
    // with their rays alone, bdpt read a tenth of the sun at most sunlit points of the daylit
    // office and several times it at one or two, and did not reach its target here.
    void sunDiscAtAWorkPlane_data() { pointLightIsExact_data(); }
    void sunDiscAtAWorkPlane() {
        QFETCH(int, method);
        QFETCH(double, target);
        QFETCH(double, bias);
        SunOverPlane s;
        const SceneSnapshot scene = sceneFromJson(s.json());
        const CalculationGrid g = squareGrid(0.8, 6, 2.0);
        const GridLayout layout = layoutGrid(g, 1.0);
        GridSettings settings = settingsFor(GridMethod(method), target);
        settings.timeLimitSeconds = 30;  // the sensor rays alone would need hours
        const GridResult r = computeGrid(scene, layout.points, g.normal(), settings);
        QVERIFY(r.converged);
        const double expected = s.illuminance * std::cos(s.zenithDeg * std::numbers::pi / 180);
        for (size_t i = 0; i < layout.points.size(); ++i)
            QVERIFY2(agrees(r, i, expected, bias, GridMethod(method), target),
                     qPrintable(QString("point %1: %2 +- %3 lx, expected %4").arg(i).arg(r.lux[i]).arg(r.errorLux[i]).arg(expected)));
    }

    // The illuminance layer under a point light: each pixel is E = I cos / r^2 averaged over the
    // floor the pixel sees (the box filter), here exact per estimate, so only the pixel averaging
    // differs (6x6 points against 4 jittered estimates per pixel: a few percent at most, mostly
    // much less; the mean over the image within 0.5%).
    void illuminanceLayerUnderAPointLight() {
        DeltaLightOverPlane s;
        s.resolution = 24;
        const SceneSnapshot scene = sceneFromJson(s.json());
        const RenderScene renderScene(scene);
        TaskSystem tasks(0);
        std::vector<float> lux;
        auto job = tasks.submit(
            [&](TaskContext& ctx) { lux = traceIlluminanceLayer(renderScene, GridMethod::Path, 4, 1, ctx); });
        job->wait();
        const std::vector<double> expected = expectedFloorImage(s.camera(), [&](const V3d& p) {
            const V3d d = V3d(0, s.h, 0) - p;
            return 683.0 * s.intensity * (s.h / d.length()) / (d.length2() * 1e-6);
        });
        QCOMPARE(lux.size(), expected.size());
        double sum = 0, sumExpected = 0, worst = 0;
        for (size_t i = 0; i < lux.size(); ++i) {
            sum += lux[i];
            sumExpected += expected[i];
            worst = std::max(worst, std::abs(lux[i] / expected[i] - 1));
        }
        QVERIFY2(std::abs(sum / sumExpected - 1) < 0.005, qPrintable(QString::number(sum / sumExpected)));
        QVERIFY2(worst < 0.05, qPrintable(QString::number(worst)));
    }

    // The illuminance layer by every backend's machinery (and the preview's) under a square
    // emitter, against Lambert's formula averaged over each pixel: the mean over the image, and
    // separately over the middle (under the emitter) and the rest, within 3% (the backends put
    // one sensor at each pixel's centre rather than box-filtering: well under 1% here). 4096
    // passes: the Metropolis chains mix slowly over 256 sensors (cmlt's middle was 3.5% off at
    // 1024 passes, 2.1% at 4096; path, ir, bdpt, mir within 0.25%, the preview 2.5%, its area
    // light being 16 shadow-mapped points per frame).
    void illuminanceLayerMatchesLambert_data() {
        QTest::addColumn<int>("method");
        for (GridMethod m : kGridMethods) QTest::newRow(gridMethodName(m)) << int(m);
    }
    void illuminanceLayerMatchesLambert() {
        QFETCH(int, method);
        RectangleOverPlane s;
        s.resolution = 16;
        const SceneSnapshot scene = sceneFromJson(s.json());
        std::vector<float> lux;
        const RenderScene renderScene(scene);
        TaskSystem tasks(0);
        const int passes = GridMethod(method) == GridMethod::Preview ? 16 : 4096;  // preview: frames
        auto job = tasks.submit(
            [&](TaskContext& ctx) { lux = traceIlluminanceLayer(renderScene, GridMethod(method), passes, 1, ctx); });
        job->wait();
        job->rethrowIfFailed();
        const auto e = s.emitter();
        const std::vector<double> expected = expectedFloorImage(
            s.camera(), [&](const V3d& p) { return 683.0 * s.radiance * lambertPolygonIrradiance(p, V3d(0, 1, 0), e); });
        QCOMPARE(lux.size(), expected.size());
        double sums[2] = {0, 0}, expectedSums[2] = {0, 0};
        for (int y = 0; y < s.resolution; ++y)
            for (int x = 0; x < s.resolution; ++x) {
                const size_t i = size_t(y) * s.resolution + x;
                const bool middle = std::abs(x - 7.5) < 4 && std::abs(y - 7.5) < 4;
                sums[middle] += lux[i];
                expectedSums[middle] += expected[i];
            }
        for (int region = 0; region < 2; ++region)
            QVERIFY2(std::abs(sums[region] / expectedSums[region] - 1) < 0.03,
                     qPrintable(QString("%1: %2").arg(region ? "middle" : "rest").arg(sums[region] / expectedSums[region])));
        const double all = (sums[0] + sums[1]) / (expectedSums[0] + expectedSums[1]);
        QVERIFY2(std::abs(all - 1) < 0.03, qPrintable(QString::number(all)));
    }

    // A point far darker than the rest (inside a closed box: leaks of a millionth) counts as
    // converged once its error bar is within the target of a thousandth of the grid's average;
    // a point as bright as the rest is held to its own value.
    void darkPointsDoNotHoldTheGridBack() {
        GridSettings settings;
        settings.targetRelativeError = 0.02;
        std::vector<BatchMeans> points(2);
        for (double x : {499.0, 500.0, 501.0}) points[0].add(x);  // +-0.5% (t = 4.3 at 2 dof)
        for (double x : {0.0, 1e-3, 2e-3}) points[1].add(x);       // +-100% of 1e-3 lx
        CancellationToken token;
        TaskContext ctx(token);
        GridResult r = emptyGridResult(2);
        QVERIFY(finishRound(points, true, settings, ctx, r, {}));
        QVERIFY(r.converged);
        QVERIFY(r.maxRelativeError < 0.02);
        points[1] = BatchMeans();
        for (double x : {100.0, 200.0, 300.0}) points[1].add(x);  // bright and noisy: not converged
        QVERIFY(!finishRound(points, true, settings, ctx, r, {}));
        QVERIFY(!r.converged && r.maxRelativeError > 0.5);
    }

    // The rounds of passes: a method that takes each pass checks after every one, alone, so its
    // rounds stay one pass; one whose values are read once a round doubles its rounds while they
    // are short against the time so far (here 100 s before the first).
    void roundsGrowWhereTheirValuesAreReadOnce() {
        CancellationToken token;
        TaskContext ctx(token);
        const GridSettings settings;
        for (RoundValues kind : {RoundValues::EachPass, RoundValues::EachRound}) {
            std::vector<int> firsts, sizes;
            double earliest = 1e300;  // seconds a take was given
            runRounds(
                settings, ctx, std::chrono::steady_clock::now() - std::chrono::seconds(100), kind,
                [&](int first, int passes) {
                    firsts.push_back(first);
                    sizes.push_back(passes);
                    return std::vector<double>(size_t(passes), 1.0);
                },
                [&](const std::vector<double>& values, int first, int passes, double seconds) {
                    earliest = std::min(earliest, seconds);
                    return first + passes >= 31;
                });
            QVERIFY(earliest >= 100);  // counted from `start`
            const std::vector<int> grown{1, 2, 4, 8, 16}, starts{0, 1, 3, 7, 15};
            if (kind == RoundValues::EachRound) {
                QCOMPARE(sizes, grown);
                QCOMPARE(firsts, starts);
            } else {
                QCOMPARE(sizes, std::vector<int>(31, 1));
            }
        }
    }

    // A grid's results as text, as `lucerna grid`, the report and the dock all show them.
    void resultsAsText() {
        QCOMPARE(formatDuration(12.34), std::string("12.3 s"));
        QCOMPARE(formatDuration(59.96), std::string("1 min 00 s"));
        QCOMPARE(formatDuration(119.7), std::string("2 min 00 s"));
        QCOMPARE(formatDuration(245.2), std::string("4 min 05 s"));
        GridResult r = emptyGridResult(4, {0, 0, 1, 0});
        r.lux = {512.34, 0.04, 0.0, 1234.5};
        r.passes = 12;
        r.samplesPerPoint = 192;
        r.seconds = 119.7;
        r.maxRelativeError = 0.0193;
        r.converged = true;
        QCOMPARE(gridErrorLines(r, 3), std::vector<std::string>{"error bar (95%) at most 1.93% of each point's value "
                                                                 "after 12 passes, 192 samples per point, 2 min 00 s"});
        r.errorBarUnknown = true;
        r.litThroughGlass = 2;
        const std::vector<std::string> unknown = gridErrorLines(r, 3);
        QCOMPARE(unknown.size(), size_t(2));
        QCOMPARE(unknown[0], std::string("path cannot carry light through glass to 2 of 3 points: use bdpt (or method auto)"));
        QVERIFY(unknown[1].starts_with("error bar unknown"));
        GridLayout layout;
        layout.nu = 2;
        layout.nv = 2;
        // Rows from the far edge down, as printf's %9.1f and %9s.
        QCOMPARE(gridTableText(layout, r), std::string("   inside   1234.5\n    512.3      0.0\n"));
        QCOMPARE(gridPointText(r, 0, 0.1, 2), std::string("51.23"));
        const GridStatistics s = gridStatistics(r.lux, r.insideGeometry);
        QCOMPARE(gridFiguresLine(s), std::string("Eavg 582.3 lx, Emin 0.0 lx, Emax 1234.5 lx, U0 0.000"));
        QCOMPARE(excludedPointsLine(s, 4), std::string("1 of 4 points inside geometry, excluded from Eavg, Emin, Emax and U0"));
    }

    // Cancelling stops the calculation at a pass boundary, with what it had.
    void cancellationStops() {
        RectangleOverPlane s;
        const RenderScene renderScene(sceneFromJson(s.json()), 8, 8);
        GridSettings settings = settingsFor(GridMethod::Path, 1e-6);  // unreachable
        settings.timeLimitSeconds = 0;
        CancellationToken token;
        TaskContext ctx(token);
        int passes = 0;
        const GridResult r = computeGridIlluminance(renderScene, {V3d(0, 0, 0)}, V3d(0, 1, 0), settings, ctx,
                                                    [&](const GridResult&) {
                                                        if (++passes == 3) token.cancel();
                                                    });
        QCOMPARE(r.passes, 3);
        QVERIFY(!r.converged);
    }

    // The command line: figures on standard output, the CSV written, bad usage one line and 2.
    void commandLine() {
        QTemporaryDir dir;
        RectangleOverPlane s;
        const QString scenePath = dir.filePath("rect.json");
        std::ofstream(scenePath.toStdString()) << s.json();
        const QString csv = dir.filePath("grid.csv");
        QProcess p;
        p.start(LUCERNA_BINARY, {"grid", scenePath, "--corner", "-1,0,1", "--u", "2,0,0", "--v", "0,0,-2", "--spacing",
                                 "0.5", "--error", "0.05", "--csv", csv});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(out.contains("4 x 4 points") && out.contains("Eavg") && out.contains("U0"), qPrintable(out));
        const CsvTable table = CsvTable::read(csv);
        QCOMPARE(int(table.rows.size()), 16);
        QCOMPARE(table.header.join(','), QString("i,j,x,y,z,illuminance_lux,error_lux,inside_geometry"));
        // The point nearest the middle sees the emitter nearly whole: compare with Lambert.
        const size_t row = 1 * 4 + 1;  // i = 1, j = 1
        QCOMPARE(table.text(row, "i") + table.text(row, "j"), QString("11"));
        const V3d x(*table.number(row, "x"), *table.number(row, "y"), *table.number(row, "z"));
        const double expected = 683.0 * s.radiance * lambertPolygonIrradiance(x, V3d(0, 1, 0), s.emitter());
        QVERIFY2(std::abs(*table.number(row, "illuminance_lux") - expected) <= 2 * *table.number(row, "error_lux"),
                 qPrintable(table.rows[row].join(',')));

        // `render --layers illuminance` adds the channel illuminance.Y (lux) beside R, G, B.
        const QString exr = dir.filePath("rect.exr");
        QProcess render;
        render.start(LUCERNA_BINARY, {"render", scenePath, "-o", exr, "--backend", "path", "--spp", "2", "--layers",
                                      "illuminance", "--illuminance-spp", "64"});
        QVERIFY(render.waitForFinished(60000));
        QCOMPARE(render.exitCode(), 0);
        const Image image = readExr(exr.toStdString());
        QVERIFY(image.channels.count("illuminance.Y"));
        QVERIFY(!image.channels.count("albedo.R"));
        // The middle 4x4 pixels look straight down at 12 cm of floor under the emitter's middle,
        // where E varies by well under 1%: their mean (1024 estimates) against the middle's E.
        const double middle = 683.0 * s.radiance * lambertPolygonIrradiance(V3d(0, 0, 0), V3d(0, 1, 0), s.emitter());
        double centre = 0;
        for (int y = image.height / 2 - 2; y < image.height / 2 + 2; ++y)
            for (int x = image.width / 2 - 2; x < image.width / 2 + 2; ++x)
                centre += image.channels.at("illuminance.Y")[size_t(y) * image.width + x] / 16.0;
        QVERIFY2(std::abs(centre / middle - 1) < 0.05, qPrintable(QString("%1 against %2").arg(centre).arg(middle)));

        QProcess bad;
        bad.start(LUCERNA_BINARY, {"grid", scenePath, "--corner", "-1,0,1", "--u", "2,0,0"});
        QVERIFY(bad.waitForFinished(30000));
        QCOMPARE(bad.exitCode(), 2);
        const QString err = QString::fromUtf8(bad.readAllStandardError()).trimmed();
        QVERIFY2(!err.contains('\n') && err.contains("--v"), qPrintable(err));

        // Backend options the method does not read: refused, not ignored.
        const QStringList grid{"grid", scenePath, "--corner", "-1,0,1", "--u", "2,0,0", "--v", "0,0,-2"};
        for (const QStringList& extra : {QStringList{"--method", "path", "--option", "max_depth=3"},
                                         QStringList{"--method", "mlt", "--option", "tries=2"}}) {
            QProcess refused;
            refused.start(LUCERNA_BINARY, grid + extra);
            QVERIFY(refused.waitForFinished(30000));
            QCOMPARE(refused.exitCode(), 2);
            const QString message = QString::fromUtf8(refused.readAllStandardError()).trimmed();
            QVERIFY2(!message.contains('\n') && message.contains("option"), qPrintable(message));
        }
    }
};

QTEST_GUILESS_MAIN(TestGrid)
#include "test_grid.moc"
