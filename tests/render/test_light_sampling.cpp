// Light sampling: chi-square of next-event directions against the pdf the MIS weights use, and
// the flux carried by emitted particles against the lights' total power in closed form.

#include "chi_square.h"
#include "render/trace/render_scene.h"
#include "render_helpers.h"

#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {
constexpr int kStatisticalTests = 4;
constexpr double kSignificance = 0.01 / kStatisticalTests;

// Three emissive triangles of different sizes and radiances around the origin, one facing away
// (it must never be sampled from the origin), a square panel of two triangles and a fan of four
// (each one cluster of the light tree, its triangles chosen by area within), plus a point light
// (delta: not part of the density).
const char* kEmitters = R"({"lucerna": 1,
  "camera": {"position": [0,0,-5], "target": [0,0,0], "fov_y": 40, "resolution": [8,8]},
  "materials": {"a": {"type": "emitter", "radiance": [1,1,1]}, "b": {"type": "emitter", "radiance": [4,2,1]}},
  "objects": [
    {"name": "up", "material": "a", "mesh": {"vertices": [[-1,2,-1],[1,2,-1],[0,2,1]], "triangles": [[0,1,2]]}},
    {"name": "side", "material": "b", "mesh": {"vertices": [[3,-0.5,-0.5],[3,-0.5,0.5],[3,0.5,0]], "triangles": [[0,1,2]]}},
    {"name": "away", "material": "b", "mesh": {"vertices": [[-2,0,-1],[-2,1,1],[-2,-1,1]], "triangles": [[0,1,2]]}},
    {"name": "panel", "material": "a", "mesh": {"quad": [[-2,3,1],[-1,3,1],[-1,3,2],[-2,3,2]]}},
    {"name": "fan", "material": "b", "mesh": {"vertices": [[1.5,1.5,0],[1,1.5,0],[1.35,1.5,0.35],[1.5,1.5,0.5],[1.85,1.5,0.35],[2,1.5,0]],
                                              "triangles": [[0,1,2],[0,2,3],[0,3,4],[0,4,5]]}}
  ],
  "lights": [{"name": "bulb", "type": "point", "position": [0,-3,0], "intensity": [1,1,1]}]})";

// Ray-triangle intersection (Moeller-Trumbore) for the reference density.
bool hitTriangle(const V3f& o, const V3f& d, const std::array<V3f, 3>& v, V3f& q) {
    const V3f e1 = v[1] - v[0], e2 = v[2] - v[0];
    const V3f p = d.cross(e2);
    const float det = e1.dot(p);
    if (std::abs(det) < 1e-12f) return false;
    const V3f s = o - v[0];
    const float u = s.dot(p) / det;
    const V3f qv = s.cross(e1);
    const float w = d.dot(qv) / det;
    const float t = e2.dot(qv) / det;
    if (u < 0 || w < 0 || u + w > 1 || t <= 0) return false;
    q = o + d * t;
    return true;
}
}  // namespace

class TestLightSampling : public QObject {
    Q_OBJECT
private slots:
    void nextEventDirections_data();
    void nextEventDirections();
    void emittedPowerMatchesClosedForm_data();
    void emittedPowerMatchesClosedForm();
    void cleanupTestCase() { QVERIFY(statisticalTests_ <= kStatisticalTests); }

private:
    int statisticalTests_ = 0;
};

void TestLightSampling::nextEventDirections_data() {
    QTest::addColumn<int>("selection");
    QTest::addColumn<bool>("receiving");  // the tree told the side that receives (+y)
    QTest::newRow("power") << int(LightSelection::Power) << false;
    QTest::newRow("tree") << int(LightSelection::Tree) << false;
    QTest::newRow("tree, receiving +y") << int(LightSelection::Tree) << true;
}

void TestLightSampling::nextEventDirections() {
    QFETCH(int, selection);
    QFETCH(bool, receiving);
    ++statisticalTests_;
    const RenderScene scene(sceneFromJson(kEmitters), 0, 0, nullptr, LightSelection(selection));
    const V3f side = receiving ? V3f(0, 1, 0) : V3f(0, 0, 0);
    SurfacePoint ref;
    ref.p = V3f(0, 0, 0);
    ref.pError = V3f(0, 0, 0);
    ref.ng = V3f(0, 0, 1);
    const auto& lights = scene.lights();
    const auto sample = [&](Rng& rng, V3f& w) {
        LightSample ls;
        const V2f u = rng.next2D();
        if (!lights.sample(ref, u, rng.next1D(), ls, side) || ls.isDelta) return false;
        w = ls.wi;
        return true;
    };
    const auto pdf = [&](const V3f& w) {
        double sum = 0;
        for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
            V3f q;
            const V3f n = scene.normalOfTriangle(t);
            if (hitTriangle(ref.p, w, scene.verticesOfTriangle(t), q) && n.dot(w) < 0)
                sum += lights.pdfEmitter(t, ref.p, q, n, side);
        }
        return sum;
    };
    const ChiSquareResult r = chiSquareSphere(sample, pdf, 40, 80, 1'000'000, 11, kSignificance);
    QVERIFY2(r.passed, r.message.c_str());
    // The delta light and the back-facing triangle take the rest of the probability; told the
    // receiving side, the tree never chooses the point light below, nor the triangle facing away.
    qInfo("integral of the pdf over the sphere: %.4f", r.pdfIntegral);
    if (receiving) QVERIFY(r.pdfIntegral > 0.98 && r.pdfIntegral < 1.01);
    else QVERIFY(r.pdfIntegral < 0.99 && r.pdfIntegral > 0.05);
}

void TestLightSampling::emittedPowerMatchesClosedForm_data() {
    QTest::addColumn<QString>("light");
    QTest::addColumn<double>("expectedY");  // luminance of the total emitted power, scene units
    const double pi = std::numbers::pi;
    // Area: pi L A; the triangle (-1,0,-1),(1,0,-1),(0,0,1) has area 2.
    QTest::newRow("area") << R"({"name": "e", "material": "lamp", "mesh": {"vertices": [[-1,0,-1],[1,0,-1],[0,0,1]], "triangles": [[0,2,1]]}})"
                          << pi * 2.0 * 3.0;
    // Point: 4 pi I / mpu^2 with mpu 0.5.
    QTest::newRow("point") << R"({"name": "p", "type": "point", "position": [0,1,0], "intensity": [3,3,3]})"
                           << 4 * pi * 3.0 / 0.25;
    // Spot, hard edge: 2 pi (1 - cos 40deg) I / mpu^2.
    QTest::newRow("spot hard") << R"({"name": "s", "type": "spot", "position": [0,1,0], "direction": [1,-1,0], "intensity": [3,3,3], "cone_angle": 40})"
                               << 2 * pi * (1 - std::cos(40 * pi / 180)) * 3.0 / 0.25;
    // Spot with falloff: 2 pi I integral of smoothstep over cos, by quadrature here.
    double smooth = 0;
    const double a = std::cos(40 * pi / 180), b = std::cos(20 * pi / 180);
    for (int i = 0; i < 100000; ++i) {
        const double c = a + (1 - a) * (i + 0.5) / 100000;
        const double t = std::clamp((c - a) / (b - a), 0.0, 1.0);
        smooth += t * t * (3 - 2 * t) * (1 - a) / 100000;
    }
    QTest::newRow("spot smooth") << R"({"name": "s", "type": "spot", "position": [0,1,0], "direction": [0,-1,0], "intensity": [3,3,3], "cone_angle": 40, "falloff_start": 20})"
                                 << 2 * pi * smooth * 3.0 / 0.25;
}

void TestLightSampling::emittedPowerMatchesClosedForm() {
    QFETCH(QString, light);
    QFETCH(double, expectedY);
    const bool isArea = light.contains("mesh");
    // A floor so that the scene has bounds; the light under test is the only emitter.
    const QString json = QString(R"({"lucerna": 1, "meters_per_unit": 0.5,
      "camera": {"position": [0,5,-5], "target": [0,0,0], "fov_y": 40, "resolution": [8,8]},
      "materials": {"floor": {"type": "diffuse", "albedo": [0.5,0.5,0.5]}, "lamp": {"type": "emitter", "radiance": [3,3,3]}},
      "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[-5,-1,-5],[-5,-1,5],[5,-1,5],[5,-1,-5]]}}%1],
      "lights": [%2]})")
                             .arg(isArea ? ", " + light : "", isArea ? "" : light);
    const RenderScene scene(sceneFromJson(json.toStdString()));
    Rng rng(5, 7);
    double sum = 0, sum2 = 0;
    const int n = 400000;
    for (int i = 0; i < n; ++i) {
        EmissionSample e;
        double y = 0;
        const V2f u1 = rng.next2D(), u2 = rng.next2D();
        if (scene.lights().sampleEmission(u1, u2, rng.next1D(), e)) {
            y = luminance(e.power);
            QVERIFY(std::abs(e.direction.length() - 1) < 1e-4f);
            if (isArea) QVERIFY(e.direction.dot(e.normal) > 0);  // one-sided
        }
        sum += y;
        sum2 += y * y;
    }
    const double mean = sum / n, sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    qInfo("mean %.6g, closed form %.6g, sigma %.3g", mean, expectedY, sigma);
    QVERIFY(std::abs(mean - expectedY) <= 4 * sigma + 1e-6 * expectedY);
    QVERIFY(std::abs(scene.lights().totalPower() / expectedY - 1) < 0.5);  // selection weights: same units
}

QTEST_GUILESS_MAIN(TestLightSampling)
#include "test_light_sampling.moc"
