// Goniometric luminaires in scenes (issue 7): the scene keys round-trip; the emission sampling's
// chi-square and normalisation; renders of a luminaire over a diffuse floor against
// E = I(C, gamma) cos / d^2 for path, bdpt (all strategies and light tracing alone), ir, mir,
// mlt, cmlt and the preview, with the luminaire turned about its nadir; and `lucerna info`.
// The files themselves: test_luminaire.

#include "chi_square.h"
#include "closed_form_scenes.h"
#include "core/photometry/luminaire.h"
#include "photometric_files.h"
#include "render/preview/preview.h"
#include "render/trace/lights/light_sampler.h"
#include "render_helpers.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace lucerna;
using namespace lucerna::test;

namespace {

double relmse(const Image& t, const std::vector<double>& r) {
    double s = 0;
    for (size_t i = 0; i < t.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = t.pixels[i][c] - r[i];
            s += d * d / (r[i] * r[i] + 1e-4);
        }
    return s / (3.0 * double(t.pixels.size()));
}

// A luminaire 2 m above a diffuse floor (albedo rho), camera halfway down looking straight at
// the floor, nothing else: the floor's radiance is rho / pi * I(C, gamma) / 683 * cos / d^2.
struct LuminaireOverPlane {
    double rho = 0.5, h = 2.0, rotationDeg = 0;
    int resolution = 24;
    std::string file;  // absolute

    Camera camera() const {
        Camera c;
        c.position = V3d(0, h / 2, 0);
        c.target = V3d(0, 0, 0);
        c.up = V3d(0, 0, 1);
        c.fovYDeg = 90;
        c.width = c.height = resolution;
        return c;
    }
    std::string json() const {
        std::ostringstream s;
        s << R"({"lucerna": 1, "camera": {"position": )" << jsonVec(camera().position)
          << R"(, "target": [0,0,0], "up": [0,0,1], "fov_y": 90, "resolution": [)" << resolution << "," << resolution
          << R"(]}, "materials": {"floor": {"type": "diffuse", "albedo": [)" << rho << "," << rho << "," << rho
          << R"(]}}, "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[-20,0,-20],[-20,0,20],[20,0,20],[20,0,-20]]}}],)"
          << R"("lights": [{"name": "lum", "type": "luminaire", "file": ")" << file << R"(", "position": [0,)" << h
          << R"(,0], "direction": [0,-1,0], "rotation": )" << rotationDeg << "}]}";
        return s.str();
    }
    // The README's convention written out independently: nadir -Y, C0 = +X turned by the
    // rotation toward C90 = C0 x nadir (C90 = -Z unturned).
    std::vector<double> expected(const GoniometricDistribution& d) const {
        const double r = rotationDeg * kDegD;
        const V3d c0(std::cos(r), 0, -std::sin(r)), c90(-std::sin(r), 0, -std::cos(r)), nadir(0, -1, 0);
        return expectedFloorImage(camera(), [&](const V3d& p) {
            const V3d toP = p - V3d(0, h, 0);
            const double dist = toP.length();
            const V3d w = toP / dist;
            const double gamma = std::acos(std::clamp(w.dot(nadir), -1.0, 1.0)) / kDegD;
            double c = std::atan2(w.dot(c90), w.dot(c0)) / kDegD;
            if (c < 0) c += 360;
            return rho / kPiD * d.intensity(c, gamma) / 683.0 * (h / dist) / (dist * dist);
        });
    }
};

}  // namespace

class TestLuminaireScenes : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(dir_.isValid()); }
    void sceneKeysRoundTrip();
    void emissionSamplingFollowsDistribution();
    void rendersAgainstClosedForm_data();
    void rendersAgainstClosedForm();
    void rotationTurnsTheImage();
    void infoComparesFluxes();

private:
    QTemporaryDir dir_;
    QString path(const QString& name) const { return dir_.path() + "/" + name; }
};

void TestLuminaireScenes::sceneKeysRoundTrip() {
    writeFile(path("rt.ies"), iesText(steps(0, 90, 5), {0}, kCosine, 2000));
    const std::string head = R"({"lucerna": 1, "camera": {"position": [0,1,0], "target": [0,0,0], "up": [0,0,1],
        "fov_y": 60, "resolution": [8, 8]}, "materials": {}, "objects": [], "lights": [)";
    const std::string json = head + R"({"name": "a", "type": "luminaire", "file": "rt.ies", "position": [1, 2, 3],
        "direction": [0, -1, 0.5], "rotation": 30, "lumens": 1200, "temperature": 3000},
        {"name": "b", "type": "luminaire", "file": "rt.ies", "position": [0, 2, 0], "direction": [0, -1, 0],
        "color": [1, 0.5, 0.25]}]})";
    const Scene s = parseScene(json, path("rt.json").toStdString());
    QCOMPARE(s.lights.size(), size_t(2));
    const Light& a = s.lights[0];
    QCOMPARE(a.type, LightType::Luminaire);
    QVERIFY(a.luminaire && a.luminaire->distribution);
    QCOMPARE(a.luminaire->distribution.get(), s.lights[1].luminaire->distribution.get());  // read once
    QCOMPARE(*a.luminaire->rotationDeg, 30.0);
    // "lumens" rescales the whole distribution: 1200 lm (the file's cosine integrates to ~100 pi).
    QVERIFY(std::abs(luminaireFlux(a) / 1200 - 1) < 1e-9);
    QVERIFY(std::abs(luminaireFlux(s.lights[1]) / a.luminaire->distribution->integratedFlux() - 1) < 1e-9);
    const std::string saved = saveSceneToString(s);
    QVERIFY(saved.find(R"("type": "luminaire", "file": "rt.ies", "position": [1, 2, 3], "direction": [0, -1, 0.5], "rotation": 30, "lumens": 1200, "temperature": 3000)") != std::string::npos);
    const Scene back = parseScene(saved, path("rt.json").toStdString());
    QVERIFY(back == s);
    QCOMPARE(saveSceneToString(back), saved);

    const auto error = [&](const std::string& light) -> std::string {
        try {
            parseScene(head + light + "]}", path("e.json").toStdString());
        } catch (const SceneError& e) {
            return e.what();
        }
        return "(no error)";
    };
    const std::string base = R"({"name": "l", "type": "luminaire", "file": "rt.ies", "position": [0, 2, 0], "direction": [0, -1, 0])";
    QVERIFY(error(base + "}") == "(no error)");
    QVERIFY(error(base + R"(, "intensity": [1, 1, 1]})").find("lights[0].intensity: unknown key for a luminaire light") != std::string::npos);
    QVERIFY(error(base + R"(, "color": [1, 1, 1], "temperature": 3000})").find("give color or temperature, not both") != std::string::npos);
    QVERIFY(error(base + R"(, "lumens": -1})").find("lights[0].lumens: must be at least 0") != std::string::npos);
    QVERIFY(error(R"({"name": "l", "type": "luminaire", "position": [0, 2, 0], "direction": [0, -1, 0]})").find("lights[0].file: required key is missing") != std::string::npos);
    QVERIFY(error(R"({"name": "l", "type": "luminaire", "file": "rt.ies", "position": [0, 2, 0], "direction": [0, 0, 0]})").find("lights[0].direction: direction must be non-zero") != std::string::npos);
}

void TestLuminaireScenes::emissionSamplingFollowsDistribution() {
    // A broad asymmetric distribution over the sphere, and a narrow beam (checked over a cap
    // around its axis), each emitted through LightSampler with the nadir along +z and a rotation,
    // against DeltaLight::pdfDirection.
    writeFile(path("broad.ies"), iesText(steps(0, 180, 5), steps(0, 360, 15), [](double c, double g) {
                  return kAsymmetric(c, g) + 50.0 * (1 + std::cos(g * kDegD));
              }));
    writeFile(path("beam.ies"), iesText(steps(0, 180, 1), steps(0, 180, 30),
                                        [](double c, double g) { return kBeam(c, g) * (1.2 + std::cos(c * kDegD)); }));
    for (const char* file : {"broad.ies", "beam.ies"}) {
        Light l;
        l.type = LightType::Luminaire;
        l.position = V3d(0, 0, 0);
        l.direction = V3d(0, 0, 1);
        l.luminaire = LuminaireSpec();
        l.luminaire->rotationDeg = 40;
        l.luminaire->distribution = std::make_shared<const GoniometricDistribution>(loadLuminaireFile(path(file).toStdString()));
        const DeltaLight delta = compileDeltaLight(l);
        const LightSampler sampler({}, {delta}, 1.0f, V3f(0, 0, 0), 1.0f, 0);
        // The emitted power is the flux: sum of power / N = intensity scale * flux (one light).
        double powerSum = 0;
        int n = 0;
        const auto sample = [&](Rng& rng, V3f& w) {
            EmissionSample es;
            if (!sampler.sampleEmission(rng.next2D(), rng.next2D(), rng.next1D(), es)) return false;
            w = es.direction;
            powerSum += double(es.power.y);
            ++n;
            return true;
        };
        const auto pdf = [&](const V3f& w) { return double(delta.pdfDirection(w)); };
        const bool beam = std::string(file) == "beam.ies";
        const ChiSquareResult r = beam ? chiSquareSphereCap(sample, pdf, std::cos(14 * kDegD), 12, 24, 400000, 7, 0.01 / 4)
                                       : chiSquareSphere(sample, pdf, 24, 48, 1000000, 11, 0.01 / 4);
        qInfo("%s: %s", file, r.message.c_str());
        QVERIFY2(r.passed, r.message.c_str());
        QVERIFY2(std::abs(r.pdfIntegral - 1) < 2e-3, qPrintable(QString::number(r.pdfIntegral)));
        const double wantPower = double(delta.intensity.y) * delta.goniometric->flux();
        qInfo("mean power %.6g, intensity x flux %.6g", powerSum / n, wantPower);
        QVERIFY(std::abs(powerSum / n / wantPower - 1) < 0.01);
        // NEE's intensity toward a direction is the table's, turned by the frame.
        const LuminaireFrame f = luminaireFrame(l.direction, 40);
        const V3d w = (f.nadir * std::cos(5 * kDegD) + f.c0 * std::sin(5 * kDegD) * std::cos(60 * kDegD) +
                       f.c90 * std::sin(5 * kDegD) * std::sin(60 * kDegD));
        QVERIFY(std::abs(delta.factor(toFloat(w)) / l.luminaire->distribution->intensity(60, 5) - 1) < 1e-4);
    }
}

void TestLuminaireScenes::rendersAgainstClosedForm_data() {
    QTest::addColumn<QString>("backend");
    QTest::addColumn<int>("spp");
    QTest::addColumn<QString>("option");
    QTest::addColumn<double>("meanTolerance");
    QTest::addColumn<double>("relmseTolerance");
    QTest::newRow("path") << "path" << 8 << "" << 0.005 << 2e-4;
    QTest::newRow("bdpt") << "bdpt" << 16 << "" << 0.01 << 3e-3;
    QTest::newRow("light tracing") << "bdpt" << 256 << "strategies=light_tracing" << 0.01 << 0.03;
    QTest::newRow("ir") << "ir" << 8 << "" << 0.005 << 2e-4;
    QTest::newRow("mir") << "mir" << 8 << "" << 0.01 << 2e-3;
    // The Metropolis backends: the mean (their normalisation) is what a small image can check;
    // their per-pixel noise at this work is large.
    QTest::newRow("mlt") << "mlt" << 16 << "" << 0.01 << 0.5;
    QTest::newRow("cmlt") << "cmlt" << 16 << "" << 0.01 << 0.5;
    QTest::newRow("preview") << "preview" << 0 << "" << 0.015 << 2e-3;
}

void TestLuminaireScenes::rendersAgainstClosedForm() {
    QFETCH(QString, backend);
    QFETCH(int, spp);
    QFETCH(QString, option);
    QFETCH(double, meanTolerance);
    QFETCH(double, relmseTolerance);
    writeFile(path("asym.ies"), iesText(steps(0, 90, 5), steps(0, 180, 15), kAsymmetric));
    LuminaireOverPlane sc;
    sc.file = path("asym.ies").toStdString();
    sc.rotationDeg = 30;
    const SceneSnapshot scene = sceneFromJson(sc.json(), path("floor.json").toStdString());
    const std::vector<double> expected = sc.expected(*scene->lights[0].luminaire->distribution);
    Image img;
    if (backend == "preview") {
        Preview preview;
        preview.setScene(scene);
        Image sum;
        for (int f = 0; f < 16; ++f) {
            preview.regenerate(uint64_t(1000 + f));
            const Image one = preview.render((f % 4 + 0.5f) / 4.0f, ((f / 4) % 4 + 0.5f) / 4.0f);
            if (f == 0) sum = Image(one.width, one.height);
            for (size_t i = 0; i < one.pixels.size(); ++i) sum.pixels[i] += one.pixels[i];
        }
        for (Rgb& p : sum.pixels) p /= 16.0f;
        img = sum;
    } else {
        RenderSettings s;
        s.spp = spp;
        s.seed = 3;
        if (!option.isEmpty()) {
            const QStringList kv = option.split('=');
            s.options[kv[0].toStdString()] = kv[1].toStdString();
        }
        img = renderFrame(backend.toStdString(), scene, s).image;
    }
    double want = 0;
    for (double e : expected) want += e;
    want /= double(expected.size());
    const double mean = channelMean(img), rel = relmse(img, expected);
    qInfo("%s: mean %.6g, closed form %.6g (%+.3f%%), relmse %.3g", qPrintable(backend), mean, want,
          100 * (mean / want - 1), rel);
    QVERIFY2(std::abs(mean / want - 1) < meanTolerance, qPrintable(QString::number(mean / want - 1)));
    QVERIFY2(rel < relmseTolerance, qPrintable(QString::number(rel)));
}

void TestLuminaireScenes::rotationTurnsTheImage() {
    // kAsymmetric is brightest toward C0. Unturned, C0 = +X; turned by 90 degrees, C0 = -Z. The
    // camera looks down -Y with up +Z: image right is -X, image top is +Z.
    writeFile(path("turn.ies"), iesText(steps(0, 90, 5), steps(0, 180, 15), kAsymmetric));
    const auto brightest = [&](double rotation) {
        LuminaireOverPlane sc;
        sc.file = path("turn.ies").toStdString();
        sc.rotationDeg = rotation;
        sc.resolution = 16;
        const Image img = render("path", sceneFromJson(sc.json(), path("turn.json").toStdString()), 2);
        double left = 0, right = 0, top = 0, bottom = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const double v = img.at(x, y).y;
                (x < img.width / 2 ? left : right) += v;
                (y < img.height / 2 ? top : bottom) += v;
            }
        return std::array<double, 4>{left, right, top, bottom};
    };
    const auto a = brightest(0), b = brightest(90);
    qInfo("rotation 0: left %.4g right %.4g top %.4g bottom %.4g", a[0], a[1], a[2], a[3]);
    qInfo("rotation 90: left %.4g right %.4g top %.4g bottom %.4g", b[0], b[1], b[2], b[3]);
    QVERIFY(a[0] > 1.5 * a[1]);                       // +X is image left
    QVERIFY(std::abs(a[2] / a[3] - 1) < 0.02);        // symmetric top to bottom
    QVERIFY(b[3] > 1.5 * b[2]);                       // -Z is image bottom
    QVERIFY(std::abs(b[0] / b[1] - 1) < 0.02);
}

void TestLuminaireScenes::infoComparesFluxes() {
    // One file whose stated flux is its integral, one that states 25% too much.
    writeFile(path("fair.ies"), iesText(steps(0, 180, 5), {0}, kIsotropic, 4 * kPiD * 100));
    writeFile(path("boast.ldt"), ldtText(1, 24, steps(0, 90, 2.5), kCosine, 1000 * kPiD * 100 / 800, 100));
    writeFile(path("absolute.ies"), iesText(steps(0, 180, 5), {0}, kIsotropic, -1));  // absolute photometry
    writeFile(path("info.json"), R"({"lucerna": 1, "camera": {"position": [0,1,0], "target": [0,0,0], "up": [0,0,1],
        "fov_y": 60, "resolution": [8, 8]}, "materials": {}, "objects": [], "lights": [
        {"name": "fair", "type": "luminaire", "file": "fair.ies", "position": [0, 2, 0], "direction": [0, -1, 0]},
        {"name": "boast", "type": "luminaire", "file": "boast.ldt", "position": [0, 2, 0], "direction": [0, -1, 0],
         "lumens": 500},
        {"name": "absolute", "type": "luminaire", "file": "absolute.ies", "position": [0, 2, 0], "direction": [0, -1, 0]}]})");
    QProcess p;
    p.start(LUCERNA_BINARY, {"info", path("info.json")});
    QVERIFY(p.waitForFinished(30000));
    const QString out = QString::fromUtf8(p.readAllStandardOutput());
    qInfo("%s", qPrintable(out));
    QCOMPARE(p.exitCode(), 0);
    QVERIFY(out.contains("lights: 3 (point 0, spot 0, directional 0, luminaire 3)"));
    QVERIFY(out.contains("absolute: luminaire, absolute.ies: file states no flux (absolute photometry), distribution "
                         "integrates to 1256.64 lm"));
    QVERIFY(out.contains("fair: luminaire, fair.ies: file states 1256.64 lm, distribution integrates to 1256.64 lm, "
                         "max 100 cd; in the scene 1256.64 lm"));
    // The EULUMDAT file states lamp flux x LOR = 392.7 lm; its table integrates to 314.1 lm.
    QVERIFY(out.contains("boast: luminaire, boast.ldt: file states 392.699 lm, distribution integrates to 314.109 lm"));
    QVERIFY(out.contains("in the scene 500 lm"));
    QVERIFY(out.contains("warning: luminaire 'boast': file states 392.699 lm, distribution integrates to 314.109 lm (-20%)"));
    QCOMPARE(out.count("warning:"), 1);
}

QTEST_MAIN(TestLuminaireScenes)
#include "test_luminaire_scenes.moc"
