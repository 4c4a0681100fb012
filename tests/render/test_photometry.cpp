// Photometric lights (core/photometry/photometric_units.h; README "Photometric lights"): lumens and candela with a
// colour or a blackbody temperature, converted to radiant intensity by 683 lm/W and Rec.709
// luminance; read, written back, rejected when malformed, and rendered as a closed form says.

#include "core/photometry/photometric_units.h"
#include "core/scene/scene_io.h"
#include "render_helpers.h"

#include <QtTest>

#include <numbers>

using namespace lucerna;
using namespace lucerna::test;

namespace {

const double pi = std::numbers::pi;

std::string sceneWith(const std::string& light, double metersPerUnit = 1.0) {
    return R"({"lucerna": 1, "meters_per_unit": )" + std::to_string(metersPerUnit) + R"(,
      "camera": {"position": [0, 1, 0], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y": 30, "resolution": [16, 16]},
      "materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
      "objects": [{"name": "floor", "material": "white", "mesh": {"quad": [[-9,0,-9],[-9,0,9],[9,0,9],[9,0,-9]]}}],
      "lights": [)" + light + "]}";
}

}  // namespace

class TestPhotometry : public QObject {
    Q_OBJECT
private slots:
    void blackbodyColours();
    void solidAngles();
    void convertsLumensAndCandela();
    void roundTripsAndStaleSpecs();
    void rejects_data();
    void rejects();
    void rendersIlluminanceOfLumens();
};

void TestPhotometry::blackbodyColours() {
    for (double k : {1000.0, 2700.0, 4000.0, 6504.0, 10000.0, 40000.0})
        QVERIFY(std::abs(luminance(blackbodyColour(k)) - 1.0) < 1e-12);
    const Rgbd warm = blackbodyColour(2700), d65ish = blackbodyColour(6504), cold = blackbodyColour(10000);
    qInfo("2700 K %.3f %.3f %.3f; 6504 K %.3f %.3f %.3f; 10000 K %.3f %.3f %.3f", warm.x, warm.y, warm.z, d65ish.x,
          d65ish.y, d65ish.z, cold.x, cold.y, cold.z);
    QVERIFY(warm.x > warm.y && warm.y > warm.z);  // incandescent: red over green over blue
    QVERIFY(cold.z > cold.x);                     // sky blue
    // A 6504 K blackbody lies close to D65, Rec.709's white: within a few percent of grey.
    for (int c = 0; c < 3; ++c) QVERIFY2(std::abs(d65ish[c] - 1.0) < 0.06, qPrintable(QString::number(d65ish[c])));
}

void TestPhotometry::solidAngles() {
    QCOMPARE(pointSolidAngle(), 4 * pi);
    // Hard edge: a cap of half-angle 60 degrees, 2 pi (1 - cos 60) = pi.
    QVERIFY(std::abs(spotSolidAngle(60, std::nullopt) - pi) < 1e-12);
    // With a falloff: integrate SPEC.md's smoothstep numerically.
    const double cone = 40, start = 15, a = std::cos(cone * pi / 180), b = std::cos(start * pi / 180);
    double omega = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double x = -1 + 2 * (i + 0.5) / n;  // cos theta
        const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
        omega += 2 * pi * t * t * (3 - 2 * t) * (2.0 / n);
    }
    QVERIFY(std::abs(spotSolidAngle(cone, start) / omega - 1.0) < 1e-6);
}

void TestPhotometry::convertsLumensAndCandela() {
    // 4 pi * 683 lm of white from a point light: 1 W/sr per channel.
    const Scene s = parseScene(sceneWith(R"({"name": "bulb", "type": "point", "position": [0, 2, 0], "lumens": )" +
                                         std::to_string(4 * pi * 683) + "}"), "p.json");
    for (int c = 0; c < 3; ++c) QVERIFY(std::abs(s.lights[0].intensity[c] - 1.0) < 1e-9);
    // 683 cd of a coloured spot: luminance 1 W/sr, in the colour's proportions.
    const Scene t = parseScene(sceneWith(R"({"name": "spot", "type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0],
        "candela": 683, "color": [2, 1, 0.5], "cone_angle": 30})"), "s.json");
    const Rgbd i = t.lights[0].intensity;
    QVERIFY(std::abs(luminance(i) - 1.0) < 1e-12);
    QVERIFY(std::abs(i.x / i.y - 2.0) < 1e-12 && std::abs(i.z / i.y - 0.5) < 1e-12);
    // Lumens of a spot spread over its own cone only.
    const Scene u = parseScene(sceneWith(R"({"name": "spot", "type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0],
        "lumens": 1000, "temperature": 3000, "cone_angle": 30, "falloff_start": 20})"), "u.json");
    const double candela = 1000 / spotSolidAngle(30, 20);
    QVERIFY(std::abs(luminance(u.lights[0].intensity) * 683 / candela - 1.0) < 1e-12);
}

void TestPhotometry::roundTripsAndStaleSpecs() {
    const std::string json = sceneWith(
        R"({"name": "bulb", "type": "point", "position": [0, 2, 0], "lumens": 800, "temperature": 2700},
           {"name": "spot", "type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "candela": 1200,
            "color": [1, 0.9, 0.8], "cone_angle": 30, "falloff_start": 20})");
    const Scene s = parseScene(json, "r.json");
    const std::string saved = saveSceneToString(s);
    QVERIFY(saved.find("\"lumens\": 800") != std::string::npos);
    QVERIFY(saved.find("\"temperature\": 2700") != std::string::npos);
    QVERIFY(saved.find("\"candela\": 1200") != std::string::npos);
    const Scene back = parseScene(saved, "r.json");
    QCOMPARE(back.lights, s.lights);
    // An edit of the intensity makes the photometric keys stale: the intensity is written.
    Scene edited = s;
    edited.lights[0].intensity *= 2.0;
    const Scene reread = parseScene(saveSceneToString(edited), "r.json");
    QVERIFY(!reread.lights[0].photometric);
    QCOMPARE(reread.lights[0].intensity, edited.lights[0].intensity);
}

void TestPhotometry::rejects_data() {
    QTest::addColumn<QString>("light");
    QTest::addColumn<QString>("message");
    const QString bulb = R"({"name": "bulb", "type": "point", "position": [0, 2, 0], )";
    QTest::newRow("intensity and lumens") << bulb + R"("intensity": [1,1,1], "lumens": 10})" << "lights[0]: give one of intensity, lumens and candela, not several";
    QTest::newRow("lumens and candela") << bulb + R"("lumens": 10, "candela": 3})" << "lights[0]: give one of intensity, lumens and candela, not several";
    QTest::newRow("negative lumens") << bulb + R"("lumens": -1})" << "lights[0].lumens: must be at least 0, got -1";
    QTest::newRow("colour without flux") << bulb + R"("intensity": [1,1,1], "color": [1,1,1]})" << "lights[0].color: only with lumens or candela";
    QTest::newRow("colour and temperature") << bulb + R"("lumens": 10, "color": [1,1,1], "temperature": 3000})" << "lights[0]: give color or temperature, not both";
    QTest::newRow("black colour") << bulb + R"("lumens": 10, "color": [0,0,0]})" << "lights[0].color: must have a positive luminance";
    QTest::newRow("temperature too low") << bulb + R"("lumens": 10, "temperature": 500})" << "lights[0].temperature: must be in [1000, 40000] kelvin, got 500";
    QTest::newRow("lumens on the sun") << R"({"name": "sun", "type": "directional", "direction": [0,-1,0], "lumens": 10})" << "lights[0].lumens: unknown key";
}

void TestPhotometry::rejects() {
    QFETCH(QString, light);
    QFETCH(QString, message);
    try {
        parseScene(sceneWith(light.toStdString()), "bad.json");
        QFAIL("accepted");
    } catch (const SceneError& e) {
        const std::string what = e.what();
        qInfo("%s", what.c_str());
        QVERIFY2(what.starts_with("bad.json: " + message.toStdString()), what.c_str());
        QVERIFY(what.find('\n') == std::string::npos);
    }
}

void TestPhotometry::rendersIlluminanceOfLumens() {
    // 2000 lm of white, 2 m above a floor of albedo 0.5, in a millimetre scene: directly below,
    // E_v = (2000 / 4 pi) / 2^2 lux, and the floor's luminance 0.5 / pi E_v cd/m^2, that is a
    // pixel value of luminance 0.5 / pi E_v / 683 (SPEC.md).
    const std::string json = sceneWith(R"({"name": "bulb", "type": "point", "position": [0, 2000, 0], "lumens": 2000})", 0.001);
    std::string scaled = json;
    // The camera and floor of sceneWith are in units; scale them to millimetres.
    scaled.replace(scaled.find("\"position\": [0, 1, 0]"), 21, "\"position\": [0, 1000, 0]");
    scaled.replace(scaled.find("[[-9,0,-9],[-9,0,9],[9,0,9],[9,0,-9]]"), 37, "[[-9000,0,-9000],[-9000,0,9000],[9000,0,9000],[9000,0,-9000]]");
    const Image img = render("path", sceneFromJson(scaled), 4);
    // The centre 2x2 pixels see the floor within 0.3 degrees of straight below (cos^3 > 0.9999).
    double centre = 0;
    for (int y = 7; y <= 8; ++y)
        for (int x = 7; x <= 8; ++x) centre += luminance(Rgbd(img.at(x, y).x, img.at(x, y).y, img.at(x, y).z)) / 4;
    const double lux = 2000 / (4 * pi) / 4.0;
    const double expected = 0.5 / pi * lux / 683;
    qInfo("centre luminance %.6g, expected %.6g", centre, expected);
    QVERIFY(std::abs(centre / expected - 1.0) < 0.01);
}

QTEST_GUILESS_MAIN(TestPhotometry)
#include "test_photometry.moc"
