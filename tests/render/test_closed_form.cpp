// Closed-form checks of every physically based backend and of auto, which combines them, each
// within 1% (SPEC.md conventions):
// a diffuse plane under a rectangular emitter (Lambert's polygon formula), a point light over a
// plane in a millimetre scene (E = I cos / r^2, r in metres), a closed sphere with an emitting
// cap (uniform radiance inside a sphere), and 1,000 point lights over a plane (the sum of
// I cos / r^2), where the light tree must also beat choosing lights by power.

#include "closed_form_scenes.h"
#include "render_helpers.h"

#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// Mean of the expected image, and the largest relative error of 8x8-pixel block means.
struct FloorComparison {
    double meanRelError = 0, worstBlockRelError = 0;
};

FloorComparison compareFloor(const Image& img, const std::vector<double>& expected) {
    double sumT = 0, sumE = 0;
    for (size_t i = 0; i < expected.size(); ++i) {
        sumT += img.pixels[i].x + img.pixels[i].y + img.pixels[i].z;
        sumE += 3 * expected[i];
    }
    FloorComparison c;
    c.meanRelError = std::abs(sumT / sumE - 1.0);
    // Blocks whose expected mean is under 5% of the brightest block's are skipped: there (a
    // spot's cone edge crossing a corner block) a relative error measures how well 36 points
    // integrate a pixel that the edge barely touches, not the renderer.
    const int b = 8;
    std::vector<std::pair<double, double>> blocks;  // (rendered, expected) block sums
    double brightest = 0;
    for (int by = 0; by + b <= img.height; by += b)
        for (int bx = 0; bx + b <= img.width; bx += b) {
            double t = 0, e = 0;
            for (int y = by; y < by + b; ++y)
                for (int x = bx; x < bx + b; ++x) {
                    t += img.at(x, y).y;
                    e += expected[size_t(y) * img.width + x];
                }
            blocks.emplace_back(t, e);
            brightest = std::max(brightest, e);
        }
    for (const auto& [t, e] : blocks)
        if (e >= 0.05 * brightest) c.worstBlockRelError = std::max(c.worstBlockRelError, std::abs(t / e - 1.0));
    return c;
}

// The bound on 8x8-block errors. Metropolis backends spend their mutations in proportion to
// brightness and their chains are correlated, so at the work these tests can afford their dim
// blocks carry 2 to 9% of noise (measured); for them the block check only catches gross local
// errors (a misplaced splat, a wrong pixel mapping) while the mean keeps the 1% bound.
double blockTolerance(const QString& backend, double tolerance) {
    return backend == "mlt" || backend == "cmlt" ? 0.15 : tolerance;
}

}  // namespace

class TestClosedForm : public QObject {
    Q_OBJECT
private slots:
    void rectangleOverPlane_data() { backends(); }
    void rectangleOverPlane();
    void deltaLightOverPlane_data();
    void deltaLightOverPlane();
    void sphereWithEmittingCap_data() { backends(); }
    void sphereWithEmittingCap();
    void finelyTessellatedBrightSphere_data();
    void finelyTessellatedBrightSphere();
    void manyPointLightsOverPlane_data();
    void manyPointLightsOverPlane();

private:
    // Every physically based backend, with the work it gets (samples per pixel).
    void backends() {
        QTest::addColumn<QString>("backend");
        QTest::addColumn<int>("spp");
        QTest::newRow("path") << "path" << 256;
        // Light-tracing splats add their own noise on top of the camera strategies: 256 spp keeps
        // it well inside the same 1% (mean) and 2% (8x8 block) bounds.
        QTest::newRow("bdpt") << "bdpt" << 256;
        // ir and mir light these scenes directly by next-event estimation, as path does; in the
        // sphere, indirect light comes from VPLs (a fresh set per pass for ir, the chain's for
        // mir), whose pass-to-pass noise is shared by every pixel: more passes.
        QTest::newRow("ir") << "ir" << 256;
        QTest::newRow("mir") << "mir" << 256;
        // Metropolis: one mutation per pixel per pass, chains correlated over passes.
        QTest::newRow("mlt") << "mlt" << 256;
        QTest::newRow("cmlt") << "cmlt" << 256;
        // auto (render/engine/measured_auto/): every candidate's pilot, then the passes where they
        // take the most off the error, the films combined by cross-fitted weights. Each of its
        // passes is a pass of two replicas of one method.
        QTest::newRow("auto") << "auto" << 128;
    }
};

void TestClosedForm::rectangleOverPlane() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    RectangleOverPlane s;
    const Image img = render(backend.toStdString(), sceneFromJson(s.json()), spp);
    const FloorComparison c = compareFloor(img, s.expected());
    qInfo("mean error %.4f%%, worst 8x8 block %.4f%%", 100 * c.meanRelError, 100 * c.worstBlockRelError);
    QVERIFY(c.meanRelError < 0.01);
    QVERIFY(c.worstBlockRelError < blockTolerance(backend, 0.02));  // noise of 16k samples a block, plus the 1% bound
}

void TestClosedForm::deltaLightOverPlane_data() {
    QTest::addColumn<QString>("backend");
    QTest::addColumn<int>("spp");
    QTest::addColumn<int>("kind");
    for (const auto& [name, kind] : {std::pair{"point", DeltaLightOverPlane::Kind::Point},
                                     std::pair{"spot", DeltaLightOverPlane::Kind::Spot},
                                     std::pair{"directional", DeltaLightOverPlane::Kind::Directional}}) {
        QTest::newRow(qPrintable(QString("path %1").arg(name))) << "path" << 64 << int(kind);
        // bdpt: the light-tracing share of the weight is small here but noisy; 512 spp keeps
        // the 8x8 blocks of the spot's falloff well within 1%.
        QTest::newRow(qPrintable(QString("bdpt %1").arg(name))) << "bdpt" << 512 << int(kind);
        QTest::newRow(qPrintable(QString("ir %1").arg(name))) << "ir" << 64 << int(kind);
        QTest::newRow(qPrintable(QString("mir %1").arg(name))) << "mir" << 64 << int(kind);
        QTest::newRow(qPrintable(QString("mlt %1").arg(name))) << "mlt" << 256 << int(kind);
        QTest::newRow(qPrintable(QString("cmlt %1").arg(name))) << "cmlt" << 256 << int(kind);
        QTest::newRow(qPrintable(QString("auto %1").arg(name))) << "auto" << 128 << int(kind);
    }
}

void TestClosedForm::deltaLightOverPlane() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    QFETCH(int, kind);
    DeltaLightOverPlane s;
    s.kind = DeltaLightOverPlane::Kind(kind);
    const Image img = render(backend.toStdString(), sceneFromJson(s.json()), spp);
    const auto expected = s.expected();
    if (s.kind == DeltaLightOverPlane::Kind::Point)
        QVERIFY(expected[expected.size() / 2 + 16] > 0.3);  // centre: 0.5/pi * 2 / 1 m^2 = 0.318
    const FloorComparison c = compareFloor(img, expected);
    qInfo("mean error %.4f%%, worst 8x8 block %.4f%%", 100 * c.meanRelError, 100 * c.worstBlockRelError);
    QVERIFY(c.meanRelError < 0.01);
    QVERIFY(c.worstBlockRelError < blockTolerance(backend, 0.01));
}

void TestClosedForm::sphereWithEmittingCap() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    for (double rho : {0.5, 0.8}) {
        SphereWithEmittingCap s;
        s.rho = rho;
        const std::string json = s.json();
        const Image img = render(backend.toStdString(), sceneFromJson(json), spp);
        const double expected = s.expectedRadiance();
        const double mean = img.mean();
        qInfo("rho %.1f: mean %.6f, closed form %.6f, error %.3f%%", rho, mean, expected, 100 * (mean / expected - 1));
        QVERIFY(std::abs(mean / expected - 1.0) < 0.01);
    }
}

// Issue 21: a closed sphere of albedo 0.8 in 32,000 triangles, 5,440 of them an emitting cap. Its
// light is mostly many bounces of indirect light, which ir and mir carry by VPLs shared by every
// pixel: a VPL set's total power varies with its particles' path lengths, and before interleaved
// sets (ir) and the fixed-point importance (mir) the mean was a few percent off after seconds.
// Three seeds each, each within 1.5%.
void TestClosedForm::finelyTessellatedBrightSphere_data() {
    QTest::addColumn<QString>("backend");
    QTest::addColumn<int>("spp");
    QTest::newRow("ir") << "ir" << 32;
    QTest::newRow("mir") << "mir" << 32;
}

void TestClosedForm::finelyTessellatedBrightSphere() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    SphereWithEmittingCap s;
    s.rho = 0.8;
    s.rings = 100;
    s.segments = 160;
    s.resolution = 32;
    const SceneSnapshot scene = sceneFromJson(s.json());
    const double expected = s.expectedRadiance();
    for (uint64_t seed : {1, 2, 3}) {
        const double mean = render(backend.toStdString(), scene, spp, seed).mean();
        qInfo("seed %d: mean %.6f, closed form %.6f, error %.3f%%", int(seed), mean, expected, 100 * (mean / expected - 1));
        QVERIFY(std::abs(mean / expected - 1.0) < 0.015);
    }
}

void TestClosedForm::manyPointLightsOverPlane_data() {
    QTest::addColumn<QString>("backend");
    QTest::addColumn<int>("spp");
    QTest::addColumn<double>("blockTolerance");  // the worst 8x8 block's relative error
    QTest::addColumn<double>("gain");            // power's per-pixel error over the tree's, at least
    QTest::newRow("path") << "path" << 64 << 0.015 << 10.0;
    // ir's and mir's VPL passes add noise of their own: more passes.
    QTest::newRow("ir") << "ir" << 256 << 0.015 << 10.0;
    QTest::newRow("mir") << "mir" << 256 << 0.015 << 10.0;
    // The tree in the bidirectional family: next-event estimation (s = 1) by the tree, its
    // probability in every strategy's weight (issue 37). A Markov chain's blocks spread wider
    // (15%, as in the other closed forms), and its noise is mostly the chain's, not the light
    // choice's: the tree need only be better (at 64 mutations a pixel, mlt 5x, cmlt 1.8x).
    QTest::newRow("bdpt") << "bdpt" << 64 << 0.015 << 10.0;
    QTest::newRow("mlt") << "mlt" << 64 << 0.15 << 1.0;
    QTest::newRow("cmlt") << "cmlt" << 64 << 0.15 << 1.0;
}

void TestClosedForm::manyPointLightsOverPlane() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    QFETCH(double, blockTolerance);
    QFETCH(double, gain);
    const ManyPointLightsOverPlane s;
    const SceneSnapshot scene = sceneFromJson(s.json());
    const std::vector<double> expected = s.expected();
    const auto renderWith = [&](const char* sampler) {
        RenderSettings settings;
        settings.spp = spp;
        settings.options["light_sampler"] = sampler;
        return renderFrame(backend.toStdString(), scene, settings).image;
    };
    // Per-pixel relative squared error against the closed form: the noise of the light choice.
    const auto relativeError = [&](const Image& img) {
        double sum = 0;
        for (size_t i = 0; i < expected.size(); ++i) sum += std::pow(img.pixels[i].y / expected[i] - 1.0, 2);
        return sum / double(expected.size());
    };
    const Image tree = renderWith("tree");
    const FloorComparison c = compareFloor(tree, expected);
    const Image power = renderWith("power");
    const double treeError = relativeError(tree), powerError = relativeError(power);
    qInfo("tree: mean error %.4f%%, worst 8x8 block %.4f%%; per-pixel relative mse: tree %.3g, power %.3g",
          100 * c.meanRelError, 100 * c.worstBlockRelError, treeError, powerError);
    QVERIFY(c.meanRelError < 0.005);
    QVERIFY(c.worstBlockRelError < blockTolerance);
    QVERIFY(treeError * gain < powerError);
}

QTEST_GUILESS_MAIN(TestClosedForm)
#include "test_closed_form.moc"
