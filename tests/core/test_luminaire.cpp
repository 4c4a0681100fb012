// Goniometric luminaires (issue 7): IES LM-63 and EULUMDAT files the test writes itself, whose
// flux is known in closed form (isotropic: 4 pi I0; cosine: pi I0; a 10 degree beam with a 2
// degree linear ramp: 2 pi I0 ((1 - cos 10) + the ramp's integral)); every symmetry mode expands
// to the same table; TILT=INCLUDE; one-line errors for malformed files; the emission sampling's
// chi-square and normalisation; and renders of a luminaire over a diffuse floor against
// E = I(C, gamma) cos / d^2 for path, bdpt (all strategies and light tracing alone), ir, mir,
// mlt, cmlt and the preview, with the luminaire turned about its nadir; and `lucerna info`.

#include "chi_square.h"
#include "closed_form_scenes.h"
#include "core/photometry/eulumdat_file.h"
#include "core/photometry/ies_file.h"
#include "core/photometry/luminaire.h"
#include "render/preview/preview.h"
#include "render/trace/lights/light_sampler.h"
#include "render_helpers.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <functional>

using namespace lucerna;
using namespace lucerna::test;

namespace {

constexpr double kPiD = std::numbers::pi;
constexpr double kDegD = kPiD / 180.0;
using Intensity = std::function<double(double cDeg, double gammaDeg)>;

std::vector<double> steps(double from, double to, double step) {
    std::vector<double> v;
    const int n = int(std::lround((to - from) / step));
    for (int i = 0; i <= n; ++i) v.push_back(from + step * i);
    return v;
}

std::string num(double x) {
    std::ostringstream s;
    s.precision(12);
    s << x;
    return s.str();
}

// An LM-63-2002 file of type C photometry, ten values a line.
std::string iesText(const std::vector<double>& vertical, const std::vector<double>& horizontal, const Intensity& I,
                    double lumensPerLamp = 1000, const std::string& tilt = "TILT=NONE", double multiplier = 1) {
    std::ostringstream s;
    s << "IESNA:LM-63-2002\n[TEST] written by test_luminaire\n[LUMINAIRE] test luminaire\n" << tilt << "\n";
    s << "1 " << num(lumensPerLamp) << " " << num(multiplier) << " " << vertical.size() << " " << horizontal.size()
      << " 1 2 0.1 0.1 0.05\n1.0 1.0 10\n";
    const auto list = [&](const std::vector<double>& v) {
        for (size_t i = 0; i < v.size(); ++i) s << num(v[i]) << ((i % 10 == 9 || i + 1 == v.size()) ? "\n" : " ");
    };
    list(vertical);
    list(horizontal);
    for (double h : horizontal) {
        std::vector<double> col;
        for (double v : vertical) col.push_back(I(h, v) / multiplier);
        list(col);
    }
    return s.str();
}

// A EULUMDAT file: mc C planes dc apart, the planes the symmetry indicator keeps, in cd/klm of
// lampFlux, light output ratio lor percent.
std::string ldtText(int isym, int mc, const std::vector<double>& gamma, const Intensity& I, double lampFlux, double lor) {
    const double dc = 360.0 / mc;
    std::ostringstream s;
    s << "Lucerna tests\n1\n" << isym << "\n" << mc << "\n" << num(dc) << "\n" << gamma.size() << "\n"
      << num(gamma.size() > 1 ? gamma[1] - gamma[0] : 0) << "\nreport\ntest luminaire\nT-1\ntest.ldt\n2026-11-23\n";
    for (int i = 0; i < 10; ++i) s << "100\n";  // dimensions, downward flux fraction
    s << num(lor) << "\n1.0\n0\n1\n1\nLED\n" << num(lampFlux) << "\n3000\n90\n20\n";
    for (int i = 0; i < 10; ++i) s << "0.5\n";
    for (int i = 0; i < mc; ++i) s << num(i * dc) << "\n";
    for (double g : gamma) s << num(g) << "\n";
    size_t first = 0, count = size_t(mc);
    if (isym == 1) count = 1;
    if (isym == 2) count = size_t(mc) / 2 + 1;
    if (isym == 3) first = size_t(mc) / 4, count = size_t(mc) / 2 + 1;
    if (isym == 4) count = size_t(mc) / 4 + 1;
    for (size_t c = first; c < first + count; ++c)
        for (double g : gamma) s << num(I(c * dc, g) * 1000.0 / lampFlux) << "\n";
    return s.str();
}

const Intensity kIsotropic = [](double, double) { return 100.0; };
const Intensity kCosine = [](double, double g) { return g <= 90 ? 100.0 * std::max(0.0, std::cos(g * kDegD)) : 0.0; };
// 10 degrees at I0, a linear ramp to 0 at 12 degrees.
const Intensity kBeam = [](double, double g) { return g <= 10 ? 5000.0 : g >= 12 ? 0.0 : 5000.0 * (12 - g) / 2; };
// Quadrant-symmetric (about both C0-C180 and C90-C270) and asymmetric in gamma.
const Intensity kQuadrant = [](double c, double g) {
    return 200.0 * (1.0 + 0.5 * std::cos(2 * c * kDegD)) * (1.0 + std::cos(g * kDegD)) + 10;
};
// Brighter toward C0 than C180 (symmetric only about C0-C180): shows which way the frame turns.
const Intensity kAsymmetric = [](double c, double g) {
    return g <= 90 ? 800.0 * (1.0 + 0.6 * std::cos(c * kDegD)) * std::cos(g * kDegD) : 0.0;
};

// The beam's flux: 2 pi (I0 (1 - cos 10) + integral over the ramp of I sin), by Simpson's rule.
double beamFlux() {
    double ramp = 0;
    const int n = 20000;
    const double a = 10 * kDegD, b = 12 * kDegD, h = (b - a) / n;
    for (int i = 0; i <= n; ++i) {
        const double g = a + i * h;
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        ramp += w * kBeam(0, g / kDegD) * std::sin(g);
    }
    ramp *= h / 3;
    return 2 * kPiD * (5000.0 * (1 - std::cos(10 * kDegD)) + ramp);
}

void writeFile(const QString& path, const std::string& text) {
    std::ofstream out(path.toStdString(), std::ios::binary);
    out << text;
}

double channelMean(const Image& img) {
    double s = 0;
    for (const Rgb& p : img.pixels) s += double(p.x) + p.y + p.z;
    return s / (3.0 * double(img.pixels.size()));
}

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

class TestLuminaire : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void fluxOfClosedForms_data();
    void fluxOfClosedForms();
    void symmetryModesExpandAlike();
    void tiltIncludeScalesIntensity();
    void iesVersionsReadAlike();
    void malformedFilesGiveOneLine();
    void sceneKeysRoundTrip();
    void emissionSamplingFollowsDistribution();
    void rendersAgainstClosedForm_data();
    void rendersAgainstClosedForm();
    void rotationTurnsTheImage();
    void infoComparesFluxes();
    void eulumdatColourTemperature();

private:
    QTemporaryDir dir_;
    QString path(const QString& name) const { return dir_.path() + "/" + name; }
};

void TestLuminaire::initTestCase() { QVERIFY(dir_.isValid()); }

void TestLuminaire::fluxOfClosedForms_data() {
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("shape");
    for (const char* f : {"ies", "ldt"})
        for (int shape = 0; shape < 3; ++shape)
            QTest::newRow((std::string(f) + (shape == 0 ? " isotropic" : shape == 1 ? " cosine" : " beam")).c_str())
                << QString(f) << shape;
}

void TestLuminaire::fluxOfClosedForms() {
    QFETCH(QString, format);
    QFETCH(int, shape);
    const Intensity& I = shape == 0 ? kIsotropic : shape == 1 ? kCosine : kBeam;
    const double want = shape == 0 ? 4 * kPiD * 100 : shape == 1 ? kPiD * 100 : beamFlux();
    // Gamma every 2.5 degrees (the beam every 1 degree, so that 10 and 12 are nodes), the whole
    // sphere or the lower half for the cosine.
    const std::vector<double> gamma = shape == 2 ? steps(0, 180, 1) : shape == 1 ? steps(0, 90, 2.5) : steps(0, 180, 2.5);
    const QString file = path("flux" + QString::number(shape) + "." + format);
    // The files state the closed form as their flux (IES: one lamp of that many lumens;
    // EULUMDAT: lamps of twice that at a light output ratio of 50%).
    if (format == "ies") writeFile(file, iesText(gamma, {0}, I, want));
    else writeFile(file, ldtText(1, 24, gamma, I, 2 * want, 50));
    const GoniometricDistribution d = loadLuminaireFile(file.toStdString());
    const double flux = d.integratedFlux();
    qInfo("flux %.6g lm, closed form %.6g (%.3f%%), stated %.6g", flux, want, 100 * (flux / want - 1), d.statedFluxLm);
    QVERIFY2(std::abs(flux / want - 1) < 0.01, qPrintable(QString::number(flux / want - 1)));
    QVERIFY(std::abs(d.statedFluxLm / want - 1) < 1e-9);
    QCOMPARE(d.cAngles.front(), 0.0);
    QCOMPARE(d.cAngles.back(), 360.0);
    QVERIFY(std::abs(d.maxIntensity() - I(0, 0)) < 1e-6 * I(0, 0));
    if (shape == 0) QVERIFY(std::abs(flux / want - 1) < 1e-9);  // exact for a constant table
    if (shape == 2) QVERIFY(std::abs(d.intensity(77, 11) - 2500.0) < 1e-6);  // halfway down the ramp, any C
}

void TestLuminaire::symmetryModesExpandAlike() {
    const std::vector<double> gamma = steps(0, 180, 5);
    // IES: horizontal angles to 360, 180 and 90 of a quadrant-symmetric distribution; to 0 and
    // to 360 of a rotationally symmetric one.
    std::vector<GoniometricDistribution> quadrant, rotational;
    for (double last : {360.0, 180.0, 90.0}) {
        const QString f = path("sym" + QString::number(last) + ".ies");
        writeFile(f, iesText(gamma, steps(0, last, 15), kQuadrant));
        quadrant.push_back(loadLuminaireFile(f.toStdString()));
    }
    // EULUMDAT: Isym 0, 2, 3, 4 of the same, 24 planes.
    for (int isym : {0, 2, 3, 4}) {
        const QString f = path("sym" + QString::number(isym) + ".ldt");
        writeFile(f, ldtText(isym, 24, gamma, kQuadrant, 1000, 100));
        quadrant.push_back(loadLuminaireFile(f.toStdString()));
    }
    const Intensity round = [](double, double g) { return 100 + g; };
    writeFile(path("round0.ies"), iesText(gamma, {0}, round));
    writeFile(path("round360.ies"), iesText(gamma, steps(0, 360, 30), round));
    writeFile(path("round.ldt"), ldtText(1, 12, gamma, round, 1000, 100));
    for (const char* f : {"round0.ies", "round360.ies", "round.ldt"})
        rotational.push_back(loadLuminaireFile(path(f).toStdString()));

    for (double c = 0; c < 360; c += 7.5)
        for (double g = 0; g <= 180; g += 2.5) {
            // At the nodes (every 15 degrees of C, 5 of gamma) the table holds the function itself.
            const bool node = std::fmod(c, 15.0) == 0 && std::fmod(g, 5.0) == 0;
            for (size_t k = 0; k < quadrant.size(); ++k) {
                const double a = quadrant[k].intensity(c, g), b = quadrant[0].intensity(c, g);
                if (std::abs(a - b) > 1e-9 * b)
                    QFAIL(qPrintable(QString("quadrant file %1 at C %2 gamma %3: %4 vs %5").arg(k).arg(c).arg(g).arg(a).arg(b)));
                if (node && std::abs(a - kQuadrant(c, g)) > 1e-9 * a)
                    QFAIL(qPrintable(QString("file %1 at node C %2 gamma %3: %4, function %5").arg(k).arg(c).arg(g).arg(a).arg(kQuadrant(c, g))));
            }
            for (const GoniometricDistribution& d : rotational)
                QVERIFY(std::abs(d.intensity(c, g) - round(c, g)) < 1e-9);
        }
    QCOMPARE(quadrant[0].name, std::string("test luminaire"));
}

void TestLuminaire::tiltIncludeScalesIntensity() {
    const std::vector<double> gamma = steps(0, 180, 10);
    const std::string tilt = "TILT=INCLUDE\n1\n3\n0 45 90\n1 0.5 0.25";
    writeFile(path("tilt.ies"), iesText(gamma, {0}, kIsotropic, 1000, tilt));
    const GoniometricDistribution d = loadLuminaireFile(path("tilt.ies").toStdString());
    QCOMPARE(d.tiltMultiplier(0), 1.0);
    QCOMPARE(d.tiltMultiplier(22.5), 0.75);
    QCOMPARE(d.tiltMultiplier(67.5), 0.375);
    QCOMPARE(d.tiltMultiplier(120), 0.25);  // clamped at the table's end
    QCOMPARE(d.intensity(0, 30), 100.0);    // the table itself is untilted
    // Mounted: the tilt is the nadir's angle from world down; hanging straight down it is 0.
    const auto scene = [&](const std::string& direction) {
        return parseScene(R"({"lucerna": 1, "camera": {"position": [0,1,0], "target": [0,0,0], "up": [0,0,1], "fov_y": 60,
            "resolution": [8, 8]}, "materials": {}, "objects": [], "lights": [{"name": "l", "type": "luminaire",
            "file": "tilt.ies", "position": [0, 2, 0], "direction": )" + direction + "}]}",
                          path("tilt.json").toStdString());
    };
    const double straight = luminaireFlux(scene("[0, -1, 0]").lights[0]);
    const double tilted = luminaireFlux(scene("[1, -1, 0]").lights[0]);
    const double sideways = luminaireFlux(scene("[0, 0, 1]").lights[0]);
    qInfo("flux straight %.6g, tilted 45 %.6g, sideways %.6g", straight, tilted, sideways);
    QVERIFY(std::abs(straight / (4 * kPiD * 100) - 1) < 1e-9);
    QVERIFY(std::abs(tilted / straight - 0.5) < 1e-9);
    QVERIFY(std::abs(sideways / straight - 0.25) < 1e-9);
}

void TestLuminaire::iesVersionsReadAlike() {
    // LM-63-2002, -2019 (new version line; the second numeric line's middle field is the file
    // generation type), -1995 and a 1986-style file with free text before TILT and no version line.
    const std::string base = iesText(steps(0, 90, 5), steps(0, 90, 15), kQuadrant);
    std::vector<std::string> texts = {base, base, base, base};
    texts[1].replace(0, 16, "IES:LM-63-2019");
    texts[1].replace(texts[1].find("1.0 1.0 10"), 10, "1.0 1.00001 10");
    texts[2].replace(0, 16, "IESNA:LM-63-1995");
    texts[3].replace(0, texts[3].find("TILT"), "A DOWNLIGHT, 1986 STYLE\nNO KEYWORDS HERE\n");
    const GoniometricDistribution first = parseIes(texts[0], "v2002.ies");
    for (size_t k = 1; k < texts.size(); ++k) {
        const GoniometricDistribution d = parseIes(texts[k], "v.ies");
        QCOMPARE(d.cAngles, first.cAngles);
        QCOMPARE(d.gammaAngles, first.gammaAngles);
        QCOMPARE(d.candela, first.candela);
    }
    std::string tiltFile = base;
    tiltFile.replace(tiltFile.find("TILT=NONE"), 9, "TILT=lamp.tlt");
    try {
        parseIes(tiltFile, "t.ies");
        QFAIL("no error");
    } catch (const LuminaireFileError& e) {
        QCOMPARE(std::string(e.what()), std::string("t.ies: line 4: TILT=lamp.tlt: a separate tilt file is not supported "
                                                    "(use TILT=INCLUDE or TILT=NONE)"));
    }
}

void TestLuminaire::malformedFilesGiveOneLine() {
    const std::vector<double> gamma = steps(0, 90, 2.5);  // 37 values
    std::string text = iesText(gamma, {0}, kCosine);
    // Drop the last seven candela values (the table's last line holds seven).
    const size_t cut = text.rfind('\n', text.size() - 2);
    writeFile(path("short.ies"), text.substr(0, cut + 1));
    const int lines = int(std::count(text.begin(), text.begin() + long(cut + 1), '\n'));
    const auto message = [&](const QString& file) -> std::string {
        try {
            loadLuminaireFile(file.toStdString());
        } catch (const LuminaireFileError& e) {
            return e.what();
        }
        return "(no error)";
    };
    const std::string shortMsg = message(path("short.ies"));
    qInfo("%s", shortMsg.c_str());
    QCOMPARE(shortMsg, (path("short.ies") + ": line " + QString::number(lines) +
                        ": expected 37 candela values, found 30").toStdString());

    std::string typeB = iesText(gamma, {0}, kCosine);
    typeB.replace(typeB.find(" 1 2 0.1"), 8, " 2 2 0.1");
    writeFile(path("typeb.ies"), typeB);
    QCOMPARE(message(path("typeb.ies")),
             (path("typeb.ies") + ": line 5: photometric type B is not supported (only type C)").toStdString());

    std::string word = iesText(gamma, {0}, kCosine);
    word.replace(word.find("1.0 1.0 10"), 10, "1.0 x 10");
    writeFile(path("word.ies"), word);
    QCOMPARE(message(path("word.ies")),
             (path("word.ies") + ": line 6: expected a number for the ballast-lamp factor (future use, or file "
                                 "generation type), found \"x\"").toStdString());

    writeFile(path("notilt.ies"), "IESNA:LM-63-2002\n[TEST] x\n1 2 3\n");
    QVERIFY(message(path("notilt.ies")).find("no TILT= line") != std::string::npos);

    std::string ldt = ldtText(1, 24, gamma, kCosine, 1000, 100);
    writeFile(path("short.ldt"), ldt.substr(0, ldt.size() - 20));
    const std::string ldtMsg = message(path("short.ldt"));
    qInfo("%s", ldtMsg.c_str());
    QVERIFY(ldtMsg.find("expected 37 intensities (cd/klm), found 3") != std::string::npos);
    QVERIFY(message(path("nothing.ies")).find("cannot read the file") != std::string::npos);
    for (const std::string& m : {shortMsg, ldtMsg}) QVERIFY(m.find('\n') == std::string::npos);

    // In a scene: the light's place, then the file's own line.
    const std::string scene = R"({"lucerna": 1, "camera": {"position": [0,1,0], "target": [0,0,0], "up": [0,0,1],
        "fov_y": 60, "resolution": [8, 8]}, "materials": {}, "objects": [], "lights": [{"name": "l",
        "type": "luminaire", "file": "short.ies", "position": [0, 2, 0], "direction": [0, -1, 0]}]})";
    try {
        parseScene(scene, path("s.json").toStdString());
        QFAIL("no error");
    } catch (const SceneError& e) {
        QCOMPARE(std::string(e.what()), path("s.json").toStdString() + ": lights[0].file: cannot load luminaire file " + shortMsg);
    }
}

void TestLuminaire::sceneKeysRoundTrip() {
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

void TestLuminaire::emissionSamplingFollowsDistribution() {
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

void TestLuminaire::rendersAgainstClosedForm_data() {
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

void TestLuminaire::rendersAgainstClosedForm() {
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

void TestLuminaire::rotationTurnsTheImage() {
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

void TestLuminaire::infoComparesFluxes() {
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

// EULUMDAT's colour temperature field states a CCT when it is a number of kelvin (the report's
// data sheets print it); a colour code or words state none.
void TestLuminaire::eulumdatColourTemperature() {
    const std::string text = ldtText(1, 24, steps(0, 180, 15), kIsotropic, 1000, 100);
    const std::string field = "\n3000\n90\n";  // the colour temperature, then Ra
    QVERIFY(text.find(field) != std::string::npos);
    const auto cct = [&](const std::string& value) {
        std::string t = text;
        t.replace(t.find(field), field.size(), "\n" + value + "\n90\n");
        return parseEulumdat(t, "cct.ldt").colourTemperatureK;
    };
    QCOMPARE(cct("3000"), std::optional<double>(3000.0));
    QCOMPARE(cct("4000 K"), std::optional<double>(4000.0));
    QCOMPARE(cct("2700k"), std::optional<double>(2700.0));
    QCOMPARE(cct("3500,0"), std::optional<double>(3500.0));
    QCOMPARE(cct("840"), std::optional<double>());  // a colour code: Ra 80+, 4000 K, but no number of kelvin
    QCOMPARE(cct("warm white"), std::optional<double>());
    QCOMPARE(cct(""), std::optional<double>());
}

QTEST_MAIN(TestLuminaire)
#include "test_luminaire.moc"
