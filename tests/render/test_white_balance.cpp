// White balance of pictures (issue 40): the Bradford matrix takes the chosen white to D65's
// (1, 1, 1), the lights' white is their flux-weighted colour, and the picture of a grey surface
// lit by a 4000 K lamp is neutral under a 4000 K balance, while false colour and the lux figures
// never change.
#include "core/photometry/light_output.h"
#include "core/photometry/photometric_units.h"
#include "render/display/display.h"
#include "render/display/white_balance.h"
#include "process_run.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace lucerna;
using lucerna::test::Run;
using lucerna::test::runLucerna;

namespace {

Rgbd apply(const Imath::M33d& m, const Rgbd& c) {
    const V3d v = V3d(c.x, c.y, c.z) * m;
    return Rgbd(v.x, v.y, v.z);
}

Light pointLight(double lumens, double kelvin) {
    Light l;
    l.type = LightType::Point;
    PhotometricSpec spec;
    spec.value = lumens;
    spec.temperatureK = kelvin;
    return withPhotometric(l, spec);
}

// A picture of one pixel of linear value `c` under `settings`.
QColor pictureOf(const Rgb& c, const DisplaySettings& settings) {
    Image image(1, 1);
    image.at(0, 0) = c;
    return toDisplayImage(image, settings).pixelColor(0, 0);
}

}  // namespace

class TestWhiteBalance : public QObject {
    Q_OBJECT
private slots:
    void matrixTakesTheWhiteToD65();
    void lightsWhiteIsTheFluxWeightedColour();
    void pictureOfAWarmLampIsNeutralWhenBalanced();
    void falseColourIsNeverBalanced();
    void commandLineWritesBalancedPngsOnly();
};

void TestWhiteBalance::matrixTakesTheWhiteToD65() {
    for (double kelvin : {2000.0, 2700.0, 4000.0, 5000.0, 10000.0}) {
        const Rgbd white = blackbodyColour(kelvin);
        const Imath::M33d m = whiteBalanceMatrix(white);
        const Rgbd out = apply(m, white);
        for (int c = 0; c < 3; ++c) QVERIFY2(std::abs(out[c] - 1.0) < 1e-9, qPrintable(QString("%1 K: %2").arg(kelvin).arg(out[c])));
        // A white warmer than D65 gains blue and loses red; a colder one the other way.
        if (kelvin < 6500) QCOMPARE_GT(m[2][2], m[0][0]);
        else QCOMPARE_LT(m[2][2], m[0][0]);
    }
    // D65 itself, and whites without a usable colour, leave the values alone.
    QVERIFY(whiteBalanceMatrix(Rgbd(1, 1, 1)) == Imath::M33d());
    QVERIFY(whiteBalanceMatrix(Rgbd(0, 1, 1)) == Imath::M33d());
    // Near 6500 K the blackbody is close to D65: the matrix is close to the identity.
    const Imath::M33d near = whiteBalanceMatrix(blackbodyColour(6504));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) QVERIFY(std::abs(near[i][j] - (i == j ? 1.0 : 0.0)) < 0.05);
    QCOMPARE(whiteBalanceLabel(WhiteBalance{WhiteReference::Temperature, 3000}, Rgbd(1, 1, 1)), std::string("3000 K"));
    QCOMPARE(whiteBalanceLabel(WhiteBalance{}, Rgbd(1, 1, 1)), std::string("D65"));
}

void TestWhiteBalance::lightsWhiteIsTheFluxWeightedColour() {
    Scene scene;
    QCOMPARE(lightsWhite(scene), Rgbd(1, 1, 1));  // no lights: D65
    scene.lights.push_back(pointLight(3000, 3000));
    scene.lights.push_back(pointLight(1000, 6500));
    const Rgbd expected = (blackbodyColour(3000) * 3000.0 + blackbodyColour(6500) * 1000.0) / 4000.0;
    const Rgbd got = lightsWhite(scene);
    for (int c = 0; c < 3; ++c) QVERIFY2(std::abs(got[c] - expected[c] / luminance(expected)) < 1e-9, qPrintable(QString::number(got[c])));
    // A light switched off does not count.
    scene.lights[0].on = false;
    const Rgbd cold = lightsWhite(scene), bb = blackbodyColour(6500);
    for (int c = 0; c < 3; ++c) QVERIFY(std::abs(cold[c] - bb[c]) < 1e-9);
    // The label reads the colour's temperature back (McCamy's formula: within 2% here).
    scene.lights[0].on = true;
    scene.lights[1].on = false;
    const std::string label = whiteBalanceLabel(WhiteBalance{WhiteReference::DominantLights, 0}, lightsWhite(scene));
    const double k = std::stod(label.substr(label.find('(') + 1));
    QVERIFY2(std::abs(k - 3000) < 60, label.c_str());
}

void TestWhiteBalance::pictureOfAWarmLampIsNeutralWhenBalanced() {
    // A grey of 0.18 lit by 4000 K light: linear values 0.18 x the lamp's colour.
    const Rgbd lamp = blackbodyColour(4000);
    const Rgb grey(float(0.18 * lamp.x), float(0.18 * lamp.y), float(0.18 * lamp.z));
    DisplaySettings settings;
    const QColor asRendered = pictureOf(grey, settings);
    QCOMPARE_GT(asRendered.red() - asRendered.blue(), 30);  // amber, as the issue saw
    settings.white = WhiteBalance{WhiteReference::Temperature, 4000};
    const QColor balanced = pictureOf(grey, settings);
    QVERIFY2(std::abs(balanced.red() - balanced.blue()) <= 1 && std::abs(balanced.red() - balanced.green()) <= 1,
             qPrintable(QString("%1 %2 %3").arg(balanced.red()).arg(balanced.green()).arg(balanced.blue())));
    // "The lights" with the lamp's own colour does the same.
    settings.white = WhiteBalance{WhiteReference::DominantLights, 0};
    settings.lights = lamp;
    QCOMPARE(pictureOf(grey, settings), balanced);
}

void TestWhiteBalance::falseColourIsNeverBalanced() {
    const Rgb warm(0.5f, 0.3f, 0.1f);
    DisplaySettings settings;
    settings.falseColour = true;
    const QColor plain = pictureOf(warm, settings);
    settings.white = WhiteBalance{WhiteReference::Temperature, 2700};
    QCOMPARE(pictureOf(warm, settings), plain);
}

void TestWhiteBalance::commandLineWritesBalancedPngsOnly() {
    QTemporaryDir dir;
    const QString scene = QStringLiteral(LUCERNA_RESOURCE_DIR) + "/scenes/cornell-box.json";
    const QString png = dir.filePath("b.png"), exr = dir.filePath("b.exr");
    const Run ok = runLucerna({"render", scene, "-o", png, "--backend", "path", "--spp", "1", "--width", "32",
                               "--height", "32", "--white-balance", "3000"});
    QVERIFY2(ok.exitCode == 0, qPrintable(ok.err));
    QVERIFY(QImage(png).width() == 32);
    const Run onExr = runLucerna({"render", scene, "-o", exr, "--spp", "1", "--white-balance", "lights"});
    QCOMPARE(onExr.exitCode, 2);
    QVERIFY2(onExr.err.contains("--white-balance needs a PNG output") && onExr.err.count('\n') <= 1, qPrintable(onExr.err));
    QVERIFY(!QFile::exists(exr));
    const Run bad = runLucerna({"render", scene, "-o", png, "--white-balance", "warm"});
    QCOMPARE(bad.exitCode, 2);
    QVERIFY2(bad.err.contains("D65, lights or a colour temperature"), qPrintable(bad.err));
}

QTEST_GUILESS_MAIN(TestWhiteBalance)
#include "test_white_balance.moc"
