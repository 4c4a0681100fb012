// The Perez all-weather sky of SPEC.md section 6 (core/daylight/perez_sky.h): its tables against
// ../shared/data/perez.txt, its quantities against hand computations of the section's formulas
// (an independent script's values: clearness, brightness, category, efficacies, the luminance
// coefficients), the sky's horizontal integral equal to Evd, and the scene file's perez sky.

#include "core/daylight/daylight.h"
#include "core/daylight/perez_sky.h"
#include "core/scene/scene_io.h"

#include <QtTest>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace lucerna;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

V3d atZenithAngle(double zenithDeg, double azimuthDeg = 90) {
    const double z = zenithDeg * kDeg, a = azimuthDeg * kDeg;
    return V3d(std::sin(z) * std::sin(a), std::cos(z), -std::sin(z) * std::cos(a));
}

bool close(double value, double expected, double relative = 1e-9) {
    return std::abs(value - expected) <= relative * std::max(1.0, std::abs(expected));
}

// One hour with its hand values: the section's formulas worked through by an independent
// script (Python, from the formulas and perez.txt alone).
struct HandHour {
    PerezInputs in;
    double epsilon, delta;
    int category;
    double evd, evn;
    PerezCoefficients k;
};

std::vector<HandHour> handHours() {
    return {
        // A bright, partly clear summer hour: category 6.
        {{500, 150, 11, 172, atZenithAngle(40)}, 3.461456747237072, 0.1478659933913544, 6, 21226.315488778917,
         50088.62199946292, {-0.9777466009, -0.3053476058, 13.025152215, -3.4721228924, 0.2077762795}},
        // Overcast (no beam), low sun in January: category 1 and its own c and d.
        {{0, 300, 5, 15, atZenithAngle(70)}, 1.0, 0.6153010096457063, 1, 31519.716851073856, 0.0,
         {-0.2076719273, -0.075309038, 12.6616347488, -3.9372205918, 0.2786145226}},
        // Very clear: eps capped at 11.9, category 8.
        {{800, 60, 14, 200, atZenithAngle(25)}, 11.9, 0.05001227370151773, 8, 8158.23645327046, 83664.59244925254,
         {-1.0082506799, -0.2355908795, 23.6377671098, -6.3732177426, 1.3247545035}},
        // Just inside category 2 (1.065 < eps < 2.8: Delta at least 0.2 for the shape), sun at 80 degrees.
        {{50, 200, 8, 100, atZenithAngle(80)}, 1.065211273239671, 0.8196218137631525, 2, 21995.1914127912,
         3959.9723394477687, {0.1190691213, -2.3133534546, 12.3655805521, -3.6255557513, -0.3136470796}},
    };
}

// E = integral of L cos over the upper hemisphere, by the midpoint rule in (cos Z, azimuth): a
// different quadrature from the model's own.
double horizontalIlluminance(const PerezSky& sky, int n = 400) {
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double mu = (i + 0.5) / n, s = std::sqrt(1 - mu * mu);
        for (int j = 0; j < 4 * n; ++j) {
            const double phi = 2 * std::numbers::pi * (j + 0.5) / (4 * n);
            sum += sky.luminance(V3d(s * std::cos(phi), mu, s * std::sin(phi))) * mu;
        }
    }
    return sum * (1.0 / n) * (2 * std::numbers::pi / (4 * n));
}

std::string perezScene(const std::string& sunKeys, const std::string& skyKeys) {
    return R"({"lucerna": 1,
"camera": {"position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40, "resolution": [16, 12]},
"materials": {"white": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
"objects": [{"name": "floor", "material": "white", "mesh": {"quad": [[-1, 0, -1], [-1, 0, 1], [1, 0, 1], [1, 0, -1]]}}],
"site": {"latitude": 48.857, "longitude": 2.352, "utc_offset": 1},
"lights": [{"name": "sun", "type": "sun")" + sunKeys + R"(}],
"sky": {"model": "perez")" + skyKeys + "}}\n";
}

std::string rejection(const std::string& text) {
    try {
        parseScene(text, "perez.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return {};
}

}  // namespace

class TestPerezSky : public QObject {
    Q_OBJECT

private slots:
    void tablesMatchTheSharedFile();
    void handComputedHours();
    void skyGivesItsDiffuseIlluminance();
    void shapeClampsAndSunBelowHorizon();
    void sceneFileAndResolve();
};

void TestPerezSky::tablesMatchTheSharedFile() {
    // The compiled tables are perez.txt's: the model's output for one input per category and
    // clearness bin, compared with the same formulas on the file's numbers.
    std::ifstream file(LUCERNA_SHARED_DIR "/data/perez.txt");
    QVERIFY2(file, "../shared/data/perez.txt is not beside the checkout");
    std::map<std::string, std::vector<std::vector<double>>> table;
    std::string line, section;
    while (std::getline(file, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (line[0] == '[') {
            section = line.substr(1, line.find(']') - 1);
            continue;
        }
        std::istringstream in(line);
        int index = 0;
        in >> index;
        std::vector<double> row;
        for (double x; in >> x;) row.push_back(x);
        table[section].push_back(row);
    }
    QCOMPARE(table["clearness_bins"].size(), size_t(8));
    QCOMPARE(table["luminance"].size(), size_t(8));
    QCOMPARE(table["diffuse_efficacy"].size(), size_t(8));
    QCOMPARE(table["direct_efficacy"].size(), size_t(8));
    for (int k = 0; k < 8; ++k) {
        // Ed fixed, Ib chosen for an epsilon in the middle of bin k at zenith 30 degrees.
        const double lo = table["clearness_bins"][size_t(k)][0], hi = std::min(table["clearness_bins"][size_t(k)][1], 11.9);
        const double eps = 0.5 * (lo + hi), z = 30 * kDeg, z3 = 1.041 * z * z * z, ed = 120;
        const double ib = ed * (eps * (1 + z3) - z3 - 1);
        const PerezSky sky({ib, ed, 11, 80, atZenithAngle(30)}, 0);
        QCOMPARE(sky.category(), k + 1);
        const double delta = sky.brightness(), w = std::exp(0.07 * 11 - 0.075);
        const auto& de = table["diffuse_efficacy"][size_t(k)];
        const auto& dn = table["direct_efficacy"][size_t(k)];
        QVERIFY(close(sky.diffuseIlluminance(), ed * (de[0] + de[1] * w + de[2] * std::cos(z) + de[3] * std::log(delta))));
        QVERIFY(close(sky.directNormalIlluminance(),
                      ib * std::max(0.0, dn[0] + dn[1] * w + dn[2] * std::exp(5.73 * z - 5) + dn[3] * delta)));
        const auto& x = table["luminance"][size_t(k)];
        const double dc = eps > 1.065 && eps < 2.8 ? std::max(delta, 0.2) : delta;
        const auto term = [&](int i) { return x[size_t(i)] + x[size_t(i) + 1] * z + dc * (x[size_t(i) + 2] + x[size_t(i) + 3] * z); };
        const PerezCoefficients& c = sky.coefficients();
        QVERIFY(close(c.a, term(0)) && close(c.b, term(4)) && close(c.e, term(16)));
        if (k > 0) QVERIFY(close(c.c, term(8)) && close(c.d, term(12)));
    }
}

void TestPerezSky::handComputedHours() {
    for (const HandHour& h : handHours()) {
        const PerezSky sky(h.in, 0);
        QVERIFY2(close(sky.clearness(), h.epsilon), qPrintable(QString::number(sky.clearness())));
        QVERIFY(close(sky.brightness(), h.delta));
        QCOMPARE(sky.category(), h.category);
        QVERIFY2(close(sky.diffuseIlluminance(), h.evd), qPrintable(QString::number(sky.diffuseIlluminance(), 'g', 17)));
        QVERIFY(close(sky.directNormalIlluminance(), h.evn));
        const PerezCoefficients& k = sky.coefficients();
        for (auto [got, want] : {std::pair{k.a, h.k.a}, {k.b, h.k.b}, {k.c, h.k.c}, {k.d, h.k.d}, {k.e, h.k.e}})
            QVERIFY2(std::abs(got - want) < 1e-9, qPrintable(QString("%1 vs %2").arg(got).arg(want)));
    }
}

void TestPerezSky::skyGivesItsDiffuseIlluminance() {
    for (const HandHour& h : handHours()) {
        const PerezSky sky(h.in);
        const double e = horizontalIlluminance(sky);
        QVERIFY2(std::abs(e / h.evd - 1) < 1e-4, qPrintable(QString("%1 vs %2").arg(e).arg(h.evd)));
        // A coarse integral (the annual calculation's) moves the scale by little.
        const PerezSky coarse(h.in, 48);
        QVERIFY(std::abs(coarse.luminanceScale() / sky.luminanceScale() - 1) < 2e-3);
    }
    // No diffuse irradiance: no sky.
    const PerezSky none({700, 0, 11, 172, atZenithAngle(30)});
    QCOMPARE(none.luminanceScale(), 0.0);
    QCOMPARE(none.clearness(), 11.9);
}

void TestPerezSky::shapeClampsAndSunBelowHorizon() {
    const PerezSky sky({500, 150, 11, 172, atZenithAngle(40)}, 0);
    // zeta' = min(zeta, 84 degrees): the gradation is flat below 6 degrees of elevation.
    const V3d at85 = atZenithAngle(85, 270), at89 = atZenithAngle(89, 270);
    const PerezCoefficients& k = sky.coefficients();
    const auto indicatrix = [&](const V3d& w) {
        const double g = std::acos(std::clamp(w.dot(sky.modelTowardSun()), -1.0, 1.0)), c = std::cos(g);
        return 1 + k.c * std::exp(k.d * g) + k.e * c * c;
    };
    QVERIFY(close(sky.relativeLuminance(at85) / indicatrix(at85), sky.relativeLuminance(at89) / indicatrix(at89)));
    QCOMPARE(sky.relativeLuminance(V3d(0, -1, 0)), 0.0);
    for (int i = 0; i < 200; ++i) QVERIFY(sky.relativeLuminance(atZenithAngle(i * 0.45, i * 7.3)) >= 0);
    // A sun below the horizon: Z taken as 90 degrees, no direct light; a sun near the zenith is
    // taken at 3 degrees.
    const PerezSky night({100, 40, 11, 172, atZenithAngle(93)}, 0);
    QVERIFY(close(night.modelZenithRad(), std::numbers::pi / 2));
    QCOMPARE(night.directNormalIlluminance(), 0.0);
    QVERIFY(night.modelTowardSun().y < 1e-12);
    const PerezSky high({100, 40, 11, 172, atZenithAngle(1)}, 0);
    QVERIFY(close(high.modelZenithRad(), 3 * kDeg));
    QCOMPARE(dayOfYear(2021, 3, 1), 60);
    QCOMPARE(dayOfYear(2020, 3, 1), 61);
    QCOMPARE(dayOfYear(2021, 12, 31), 365);
}

void TestPerezSky::sceneFileAndResolve() {
    const std::string text = perezScene(R"(, "time": "2021-06-21T12:30")",
                                        R"(, "direct_normal_irradiance": 500, "diffuse_horizontal_irradiance": 150, "dew_point": 11)");
    const Scene scene = parseScene(text, "perez.json");
    QVERIFY(scene.sky && scene.sky->model == SkyModelType::Perez);
    QCOMPARE(scene.sky->diffuseHorizontalIrradiance, 150.0);
    QVERIFY(!scene.lights[0].sun->illuminanceGiven);
    QVERIFY(parseScene(saveSceneToString(scene), "again.json") == scene);  // round trip

    const Daylight d = resolveDaylight(scene);
    QVERIFY(d.sun && d.sky && d.sky->perez);
    QCOMPARE(d.sky->dayOfYear, 172);
    const PerezSky& p = *d.sky->perez;
    QCOMPARE(d.sun->illuminanceLux, p.directNormalIlluminance());
    QVERIFY(p.directNormalIlluminance() > 0);
    QVERIFY(std::abs(d.sky->horizontalIlluminance - p.diffuseIlluminance()) < 1e-9 * p.diffuseIlluminance());
    // The resolved luminance is the model's, and the ground is rho (Evd + Evn cos Z) / pi.
    const V3d w = atZenithAngle(50, 200);
    QVERIFY(close(d.sky->luminance(w), p.luminance(w), 1e-9));
    const double eh = p.diffuseIlluminance() + p.directNormalIlluminance() * d.sun->towardSun.y;
    QVERIFY(close(d.sky->groundLuminance, 0.2 * eh / std::numbers::pi, 1e-12));

    // One-line rejections.
    QVERIFY(rejection(perezScene(R"(, "illuminance": 80000, "time": "2021-06-21T12:30")",
                                 R"(, "direct_normal_irradiance": 1, "diffuse_horizontal_irradiance": 1)"))
                .find("no \"illuminance\"") != std::string::npos);
    QVERIFY(rejection(perezScene(R"(, "direction": [0, -1, 0])",
                                 R"(, "direct_normal_irradiance": 1, "diffuse_horizontal_irradiance": 1)"))
                .find("\"time\"") != std::string::npos);
    QVERIFY(rejection(perezScene(R"(, "time": "2021-06-21T12:30")", R"(, "diffuse_horizontal_irradiance": 1)"))
                .find("direct_normal_irradiance") != std::string::npos);
    QVERIFY(rejection(perezScene(R"(, "time": "2021-06-21T12:30")",
                                 R"(, "direct_normal_irradiance": -1, "diffuse_horizontal_irradiance": 1)"))
                .find("at least 0") != std::string::npos);
    QVERIFY(rejection(perezScene(R"(, "time": "2021-06-21T12:30")",
                                 R"(, "direct_normal_irradiance": 1, "diffuse_horizontal_irradiance": 1, "zenith_luminance": 5)"))
                .find("zenith_luminance") != std::string::npos);
    // Without a perez sky a sun needs its illuminance.
    std::string noSky = perezScene(R"(, "time": "2021-06-21T12:30")", "");
    noSky = noSky.substr(0, noSky.find(",\n\"sky\"")) + "}\n";
    QVERIFY(rejection(noSky).find("illuminance") != std::string::npos);
}

QTEST_APPLESS_MAIN(TestPerezSky)
#include "test_perez_sky.moc"
