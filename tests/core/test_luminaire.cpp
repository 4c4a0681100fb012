// Goniometric luminaire files (issue 7): IES LM-63 and EULUMDAT files the test writes itself
// (tests/support/photometric_files.h), whose flux is known in closed form; every symmetry mode
// expands to the same table; TILT=INCLUDE; the IES versions read alike; one-line errors for
// malformed files; EULUMDAT's colour temperature. Luminaires in scenes and renders:
// test_luminaire_scenes.

#include "core/photometry/eulumdat_file.h"
#include "core/photometry/ies_file.h"
#include "core/photometry/luminaire.h"
#include "core/scene/scene_io.h"
#include "photometric_files.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace lucerna;
using namespace lucerna::test;

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
