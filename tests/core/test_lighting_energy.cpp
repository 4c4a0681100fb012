// The lighting energy of EN 15193-1 (README, "Energy (LENI; an addition)"): LENI worked by hand
// for a constructed project (12 luminaires of 30 W on 60 m²) with the office defaults and then
// with every factor given, the expected numbers written out from the formula with literal
// numbers; a luminaire's power from its file and circuit_watts over it; lights switched off;
// "not computed" when a light states no power; the "energy" and "circuit_watts" keys parsed
// strictly and written back exactly; the report's section and `lucerna info`.

#include "core/scene/scene_energy.h"
#include "core/scene/scene_io.h"
#include "process_run.h"
#include "report/luminaire_schedule.h"
#include "report/report_writer.h"

#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace lucerna;
using namespace lucerna::test;

namespace {

const std::string kData = LUCERNA_TEST_DATA_DIR;
const std::string kCase = kData + "/case.json";
const std::string kPanel = std::string(LUCERNA_RESOURCE_DIR) + "/scenes/luminaires/office_panel.ies";  // states 30 W

// A 10 m x 6 m floor (60 m² in plan) under twelve point lights of 30 W each (4 x 3, inside the
// floor's extent), then `extraLights` and the top-level `extra` keys.
std::string project(const std::string& energy, const std::string& extraLights = {}) {
    std::string lights;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j)
            lights += std::string(lights.empty() ? "" : ",\n    ") + R"({"name": "p)" + std::to_string(i) +
                      std::to_string(j) + R"(", "type": "point", "position": [)" + std::to_string(1.25 + 2.5 * i) +
                      ", 2.8, " + std::to_string(1 + 2 * j) + R"(], "lumens": 3000, "circuit_watts": 30})";
    return R"({"lucerna": 1,
  "camera": {"position": [5, 1.6, 3], "target": [5, 1, 0], "fov_y": 50, "resolution": [32, 24]},
  "materials": {"floor": {"type": "diffuse", "albedo": [0.3, 0.3, 0.3]}},
  "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[0, 0, 0], [0, 0, 6], [10, 0, 6], [10, 0, 0]]}}],
  "lights": [
    )" + lights + extraLights + "\n  ]" + (energy.empty() ? "" : ",\n  \"energy\": " + energy) + "\n}\n";
}

bool close(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

std::string rejection(const std::string& json) {
    try {
        parseScene(json, kCase);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

class TestLightingEnergy : public QObject {
    Q_OBJECT
private slots:
    void officeDefaultsByHand();
    void givenFactorsByHand();
    void buildingTypeHours();
    void luminaireFilePowerAndCircuitWatts();
    void notComputed();
    void rejects_data();
    void rejects();
    void roundTrips();
    void reportSectionAndInfo();
};

// Office: tD 2250 h, tN 250 h, Fc = Fo = FD = 1 (no controls), parasitic energy by the quick
// method's 5 + 1 kWh/(m²·a), A the extent in plan.
void TestLightingEnergy::officeDefaultsByHand() {
    const SceneEnergy s = sceneEnergy(parseScene(project(R"({"building_type": "office"})"), kCase));
    QVERIFY2(s.energy, s.notComputed.c_str());
    const LightingEnergy& e = *s.energy;
    const double wl = 12 * 30 * 1.0 * (2250 * 1.0 * 1.0 + 250 * 1.0) / 1000;  // 900 kWh/a
    const double wp = 5 * 60.0 + 1 * 60.0;                                    // 360 kWh/a
    QVERIFY(close(e.lightingKWh, wl));
    QVERIFY(close(e.lightingKWh, 900));
    QVERIFY(close(e.parasiticKWh, wp));
    QVERIFY(close(e.areaM2.value, 60) && !e.areaM2.given);
    QVERIFY(close(e.leni, (wl + wp) / 60));
    QVERIFY(close(e.leni, 21));
    QCOMPARE(e.luminaires, 12);
    QVERIFY(close(e.installedWatts, 360));
    QVERIFY(!e.daytimeHours.given && e.daytimeHours.value == 2250 && e.nightHours.value == 250);
    QVERIFY(!e.constantIlluminanceFactor.given && e.constantIlluminanceFactor.value == 1);
    QVERIFY(!e.occupancyFactor.given && !e.daylightFactor.given && e.daylightFactor.value == 1);
    QVERIFY(!e.controlParasiticWatts && !e.emergencyChargingWatts);
    QCOMPARE(s.types.size(), size_t(1));
    QCOMPARE(s.types[0].names.size(), size_t(12));
    QVERIFY(!s.types[0].fromFile);
    QCOMPARE(describeLeni(s, false),
             std::string("LENI 21.00 kWh/(m2 a) (W_L 900.0 kWh/a, W_P 360.0 kWh/a, A 60.0 m2)"));
}

void TestLightingEnergy::givenFactorsByHand() {
    const Scene scene = parseScene(
        project(R"({"building_type": "office", "daytime_hours": 2000, "night_time_hours": 500,
    "constant_illuminance_factor": 0.9, "occupancy_dependency_factor": 0.8, "daylight_dependency_factor": 0.7,
    "control_parasitic_watts": 0.5, "emergency_charging_watts": 1.5, "emergency_charging_hours": 4000, "area_m2": 50})"),
        kCase);
    const SceneEnergy s = sceneEnergy(scene);
    QVERIFY2(s.energy, s.notComputed.c_str());
    const LightingEnergy& e = *s.energy;
    const double wl = 12 * 30 * 0.9 * (2000 * 0.8 * 0.7 + 500 * 0.8) / 1000;       // 492.48 kWh/a
    const double wpc = 12 * 0.5 * (8760 - 2000 - 500) / 1000.0;                     // 37.56 kWh/a
    const double wpe = 12 * 1.5 * 4000 / 1000.0;                                    // 72 kWh/a
    QVERIFY(close(e.lightingKWh, wl));
    QVERIFY(close(e.lightingKWh, 492.48));
    QVERIFY(close(e.controlParasiticKWh, wpc));
    QVERIFY(close(e.emergencyParasiticKWh, wpe));
    QVERIFY(close(e.parasiticKWh, 109.56));
    QVERIFY(close(e.leni, (492.48 + 109.56) / 50));
    QVERIFY(e.daytimeHours.given && e.nightHours.given && e.constantIlluminanceFactor.given && e.occupancyFactor.given &&
            e.daylightFactor.given && e.emergencyChargingHours.given && e.areaM2.given);
    QVERIFY(close(s.planAreaM2, 60));  // the plan's extent, not used: area_m2 is given

    // A charging power without its hours: the charger on all year (8760 h).
    Scene noHours = scene;
    noHours.energy->emergencyChargingHours.reset();
    const LightingEnergy f = *sceneEnergy(noHours).energy;
    QVERIFY(!f.emergencyChargingHours.given);
    QVERIFY(close(f.emergencyParasiticKWh, 12 * 1.5 * 8760 / 1000.0));
}

// EN 15193:2007 Table F.1's hours, as the README states them.
void TestLightingEnergy::buildingTypeHours() {
    const std::vector<std::tuple<const char*, double, double>> table = {
        {"office", 2250, 250},    {"education", 1800, 200}, {"hospital", 3000, 2000}, {"hotel", 3000, 2000},
        {"restaurant", 1250, 1250}, {"sports", 2000, 2000}, {"retail", 3000, 1000},   {"manufacturing", 2500, 1500}};
    QCOMPARE(buildingTypes().size(), table.size());
    for (const auto& [key, tD, tN] : table) {
        const BuildingTypeHours* t = findBuildingType(key);
        QVERIFY2(t, key);
        QCOMPARE(t->daytimeHours, tD);
        QCOMPARE(t->nightHours, tN);
    }
    // Hospitals: 12 x 30 W x (3000 + 2000) h.
    const SceneEnergy s = sceneEnergy(parseScene(project(R"({"building_type": "hospital"})"), kCase));
    QVERIFY(close(s.energy->lightingKWh, 12 * 30 * (3000 + 2000) / 1000.0));
}

// A luminaire takes the power its file states (office_panel.ies: 30 W) unless circuit_watts
// gives it; lights switched off are not counted at all.
void TestLightingEnergy::luminaireFilePowerAndCircuitWatts() {
    const std::string extra = R"(,
    {"name": "panel a", "type": "luminaire", "file": ")" + kPanel + R"(", "position": [2, 2.9, 2], "direction": [0, -1, 0]},
    {"name": "panel b", "type": "luminaire", "file": ")" + kPanel + R"(", "position": [4, 2.9, 2], "direction": [0, -1, 0], "circuit_watts": 24},
    {"name": "dark", "type": "spot", "position": [5, 2.9, 2], "direction": [0, -1, 0], "lumens": 500, "cone_angle": 30, "on": false},
    {"name": "daylight", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]})";
    const Scene scene = parseScene(project(R"({"building_type": "office"})", extra), kCase);
    QCOMPARE(circuitWatts(scene.lights[12]).value_or(-1), 30.0);
    QCOMPARE(circuitWatts(scene.lights[13]).value_or(-1), 24.0);
    QVERIFY(!circuitWatts(scene.lights[14]));
    QVERIFY(!circuitWatts(scene.lights[15]));
    const SceneEnergy s = sceneEnergy(scene);
    QVERIFY2(s.energy, s.notComputed.c_str());
    QCOMPARE(s.lights, 14);
    QVERIFY(close(s.energy->installedWatts, 12 * 30 + 30 + 24));
    QVERIFY(close(s.energy->lightingKWh, (12 * 30 + 30 + 24) * (2250 + 250) / 1000.0));
    QCOMPARE(s.types.size(), size_t(3));
    QVERIFY(s.types[1].fromFile && s.types[1].file == kPanel);
    QVERIFY(!s.types[2].fromFile && s.types[2].wattsEach == 24);
    // The schedule's power is the same circuit power.
    const Schedule schedule = luminaireSchedule(scene);
    QVERIFY(schedule.totalWatts && close(*schedule.totalWatts, 12 * 30 + 30 + 24));
    QCOMPARE(schedule.withoutWatts, 0);
}

void TestLightingEnergy::notComputed() {
    const std::string bare = R"(,
    {"name": "bare", "type": "point", "position": [1, 2, 1], "lumens": 800})";
    const SceneEnergy one = sceneEnergy(parseScene(project(R"({"building_type": "office"})", bare), kCase));
    QVERIFY(!one.energy);
    QCOMPARE(one.notComputed, std::string("1 light states no power (give circuit_watts)"));
    QCOMPARE(one.withoutPower, std::vector<std::string>{"bare"});
    QCOMPARE(describeLeni(one), std::string("LENI not computed: 1 light states no power (give circuit_watts)"));
    const std::string two = bare + R"(,
    {"name": "bare spot", "type": "spot", "position": [1, 2, 1], "direction": [0, -1, 0], "lumens": 800, "cone_angle": 20})";
    const SceneEnergy both = sceneEnergy(parseScene(project(R"({"building_type": "office"})", two), kCase));
    QCOMPARE(both.notComputed, std::string("2 lights state no power (give circuit_watts)"));
    // Switched off, it is not counted: computed again.
    const std::string off = R"(,
    {"name": "bare", "type": "point", "position": [1, 2, 1], "lumens": 800, "on": false})";
    QVERIFY(sceneEnergy(parseScene(project(R"({"building_type": "office"})", off), kCase)).energy);
    // No building type: nothing to take the hours from.
    const SceneEnergy none = sceneEnergy(parseScene(project({}), kCase));
    QVERIFY(!none.energy);
    QVERIFY(none.notComputed.find("no building type") == 0);
    // The computation refuses settings that span more than a year.
    EnergySettings s;
    s.daytimeHours = 8600;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, computeLightingEnergy(s, std::vector<double>{30}, 60));
    QCOMPARE(energySettingsProblem(s),
             std::string("daytime_hours 8600 + night_time_hours (office's) 250 = 8850 h, more than the 8760 h of a year"));
}

void TestLightingEnergy::rejects_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("place");
    QTest::addColumn<QString>("problem");
    const auto row = [](const char* tag, const std::string& json, const char* place, const char* problem) {
        QTest::newRow(tag) << QByteArray::fromStdString(json) << QString(place) << QString(problem);
    };
    const auto energy = [](const std::string& body) { return project(body); };
    row("not an object", energy("3"), "energy", "expected an object, got a number");
    row("no building type", energy(R"({"daytime_hours": 2000})"), "energy.building_type", "required key is missing");
    row("unknown building type", energy(R"({"building_type": "castle"})"), "energy.building_type",
        "unknown building type \"castle\" (expected one of: office, education, hospital, hotel, restaurant, sports, retail, manufacturing)");
    row("building type not a string", energy(R"({"building_type": 1})"), "energy.building_type", "expected a string, got a number");
    row("unknown key", energy(R"({"building_type": "office", "fc": 0.9})"), "energy.fc", "unknown key (expected one of: building_type,");
    row("hours beyond a year", energy(R"({"building_type": "office", "daytime_hours": 9000})"), "energy.daytime_hours",
        "must be in [0, 8760] h, got 9000");
    row("negative night hours", energy(R"({"building_type": "office", "night_time_hours": -1})"), "energy.night_time_hours",
        "must be in [0, 8760] h, got -1");
    row("hours together beyond a year", energy(R"({"building_type": "hospital", "daytime_hours": 7000})"), "energy",
        "daytime_hours 7000 + night_time_hours (hospital's) 2000 = 9000 h, more than the 8760 h of a year");
    row("factor above 1", energy(R"({"building_type": "office", "occupancy_dependency_factor": 1.2})"),
        "energy.occupancy_dependency_factor", "must be in [0, 1], got 1.2");
    row("factor not a number", energy(R"({"building_type": "office", "daylight_dependency_factor": "1"})"),
        "energy.daylight_dependency_factor", "expected a number, got a string");
    row("negative parasitic power", energy(R"({"building_type": "office", "control_parasitic_watts": -0.5})"),
        "energy.control_parasitic_watts", "must be in [0, 1e+06] W, got -0.5");
    row("charging hours beyond a year", energy(R"({"building_type": "office", "emergency_charging_hours": 9000})"),
        "energy.emergency_charging_hours", "must be in [0, 8760] h, got 9000");
    row("zero area", energy(R"({"building_type": "office", "area_m2": 0})"), "energy.area_m2", "must be in (0, 1e+09] m2, got 0");
    const auto light = [](const std::string& body) { return project(R"({"building_type": "office"})", ",\n    " + body); };
    row("negative circuit watts", light(R"({"name": "x", "type": "point", "position": [1, 2, 1], "intensity": [1, 1, 1], "circuit_watts": -3})"),
        "lights[12].circuit_watts", "must be in [0, 1e+06] W, got -3");
    row("circuit watts not a number", light(R"({"name": "x", "type": "point", "position": [1, 2, 1], "intensity": [1, 1, 1], "circuit_watts": "30 W"})"),
        "lights[12].circuit_watts", "expected a number, got a string");
    row("circuit watts on daylight", light(R"({"name": "x", "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1], "circuit_watts": 3})"),
        "lights[12].circuit_watts", "unknown key for a directional light");
    row("circuit watts on a luminaire", light(R"({"name": "x", "type": "luminaire", "file": ")" + kPanel +
                                              R"(", "position": [1, 2, 1], "direction": [0, -1, 0], "circuit_watts": null})"),
        "lights[12].circuit_watts", "expected a number, got null");
}

void TestLightingEnergy::rejects() {
    QFETCH(QByteArray, json);
    QFETCH(QString, place);
    QFETCH(QString, problem);
    const QString message = QString::fromStdString(rejection(json.toStdString()));
    const QString head = QString::fromStdString(kCase) + ": " + place + ": ";
    QVERIFY2(message.startsWith(head), qPrintable("message: " + message + "\nexpected start: " + head));
    QVERIFY2(message.mid(head.size()).contains(problem), qPrintable("message: " + message + "\nexpected problem: " + problem));
    QVERIFY2(!message.contains('\n'), qPrintable(message));
}

// Written back with the keys given and nothing else, read back equal, stable on a second save.
void TestLightingEnergy::roundTrips() {
    const std::string extra = R"(,
    {"name": "panel", "type": "luminaire", "file": ")" + kPanel + R"(", "position": [2, 2.9, 2], "direction": [0, -1, 0], "circuit_watts": 27.5},
    {"name": "spot", "type": "spot", "position": [5, 2.9, 2], "direction": [0, -1, 0], "lumens": 500, "cone_angle": 30, "circuit_watts": 0})";
    const std::string all = R"({"building_type": "retail", "daytime_hours": 2999.5, "night_time_hours": 0.1, "constant_illuminance_factor": 0.9, "occupancy_dependency_factor": 1, "daylight_dependency_factor": 0, "control_parasitic_watts": 0.3, "emergency_charging_watts": 1.1, "emergency_charging_hours": 8760, "area_m2": 123.25})";
    for (const std::string& energy : {all, std::string(R"({"building_type": "manufacturing"})"),
                                      std::string(R"({"building_type": "sports", "area_m2": 0.001})")}) {
        const Scene s = parseScene(project(energy, extra), kCase);
        const std::string text = saveSceneToString(s);
        QVERIFY2(text.find("\"energy\": " + energy + "\n}") != std::string::npos, text.c_str());
        QVERIFY(text.find(R"("direction": [0, -1, 0], "circuit_watts": 27.5})") != std::string::npos);
        QVERIFY(text.find(R"("cone_angle": 30, "circuit_watts": 0})") != std::string::npos);
        QVERIFY(text.find(R"("lumens": 3000, "circuit_watts": 30})") != std::string::npos);
        const Scene back = parseScene(text, kCase);
        QVERIFY(back == s);
        QCOMPARE(saveSceneToString(back), text);
    }
    // Without the keys nothing is written.
    const std::string plain = saveSceneToString(parseScene(project({}), kCase));
    QVERIFY(plain.find("energy") == std::string::npos);
    // The scene compares the settings: a changed factor is a different scene.
    Scene a = parseScene(project(all), kCase), b = a;
    b.energy->occupancyFactor = 0.95;
    QVERIFY(!(a == b));
    b = a;
    b.lights[0].circuitWatts.reset();
    QVERIFY(!(a == b));
}

// The report's section states the standard, every factor, the powers, W_L, W_P, A and LENI;
// `lucerna info` prints LENI.
void TestLightingEnergy::reportSectionAndInfo() {
    if (QStandardPaths::findExecutable("pdftotext").isEmpty())
        QFAIL("pdftotext (poppler-utils) is missing: packaging/install-deps.sh installs it");
    QTemporaryDir dir;
    const QString scenePath = dir.filePath("energy.json");
    {
        QFile f(scenePath);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray::fromStdString(project(
            R"({"building_type": "office", "occupancy_dependency_factor": 0.8, "control_parasitic_watts": 0.5})")));
    }
    const Scene scene = loadScene(scenePath.toStdString());
    ReportData data;
    data.projectName = "Energy check";
    data.sceneFile = "energy.json";
    data.date = "2024-01-01";
    data.software = "Lucerna test";
    data.scene = std::make_shared<const Scene>(scene);
    data.schedule = luminaireSchedule(scene);
    data.energy = sceneEnergy(scene);
    data.maintenance = maintenanceStatement(scene);
    const QString pdf = dir.filePath("energy.pdf");
    QVERIFY(writeReportPdf(data, pdf.toStdString()) >= 2);
    const Run text = runProgram("pdftotext", {pdf, "-"});
    QCOMPARE(text.exitCode, 0);
    // W_L = 360 W x 1 x (2250 x 0.8 x 1 + 250 x 0.8) / 1000 = 720 kWh/a; W_P = 12 x 0.5 W x (8760 -
    // 2500) h / 1000 + 1 x 60 = 37.56 + 60 kWh/a; LENI = (720 + 97.56) / 60.
    const double leni = (360 * (2250 * 0.8 + 250 * 0.8) / 1000 + 12 * 0.5 * (8760 - 2500) / 1000 + 60) / 60;
    const QString out = text.out.simplified();
    for (const QString& s : {QStringLiteral("Lighting energy (LENI)"), QStringLiteral("EN 15193-1:2017"),
                             QStringLiteral("Offices (tD 2250 h, tN 250 h by default)"),
                             QStringLiteral("2250 h/a (offices' default, EN 15193:2007 Table F.1)"),
                             QStringLiteral("1.00 (default: no constant-illuminance control)"),
                             QStringLiteral("0.80 (given)"), QStringLiteral("1.00 (default: no daylight control)"),
                             QStringLiteral("0.50 W per luminaire (given)"),
                             QStringLiteral("not given: 1 kWh/(m\u00b2\u00b7a) \u00d7 A, the quick method's default (60.0 kWh/a)"),
                             QStringLiteral("60.0 m\u00b2 (the geometry's extent in plan)"), QStringLiteral("circuit_watts"),
                             QStringLiteral("720.0 kWh/a"), QStringLiteral("97.6 kWh/a (controls 37.6, emergency 60.0)"),
                             QStringLiteral("%1 kWh/(m\u00b2\u00b7a)").arg(leni, 0, 'f', 2)})
        QVERIFY2(out.contains(s), qPrintable(s + "\n---\n" + out.left(4000)));

    const Run info = runLucerna({"info", scenePath});
    QCOMPARE(info.exitCode, 0);
    QVERIFY2(info.out.contains(QStringLiteral("energy: LENI %1 kWh/(m2 a) (W_L 720.0 kWh/a, W_P 97.6 kWh/a, A 60.0 m2)")
                                   .arg(leni, 0, 'f', 2)),
             qPrintable(info.out));
}

QTEST_MAIN(TestLightingEnergy)
#include "test_lighting_energy.moc"
