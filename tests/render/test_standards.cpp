// What a designer's deliverable reads (issue 24): maintenance factors (CIE 97) and the maintained
// values they give, the luminous opening, watts and Ra that luminaire files state, task areas
// and their EN 12464-1 checks (both editions: the bundled 2021 entries, the 2011 fallback, the
// 2021 checks of Ez, walls and ceiling, the modelling ratio), the project's keys and the
// edition's; their file format both ways and its errors; `lucerna standards`.

#include "process_run.h"
#include "core/photometry/goniometric_distribution.h"
#include "core/photometry/ies_file.h"
#include "core/photometry/lighting_standards.h"
#include "core/photometry/luminaire.h"
#include "core/scene/scene_io.h"
#include "render/display/false_colour.h"
#include "render/photometry/grid_calculation.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <charconv>
#include <cmath>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// A number the output prints ("512.3"), read back in the C locale as it was written.
double decimal(const QString& text) {
    const std::string s = text.toStdString();
    double x = std::nan("");
    std::from_chars(s.data(), s.data() + s.size(), x);
    return x;
}

const std::string kResources = LUCERNA_RESOURCE_DIR;

// A room-less test plane lit by a point light, a luminaire, an emitter panel and (withSun) the
// sun; `extra` goes after the lights (top-level keys), `lightExtra` into the point light.
std::string sceneJson(const std::string& extra = {}, const std::string& lightExtra = {}, bool withSun = true) {
    return R"({"lucerna": 1,
  "camera": {"position": [0, 2, 6], "target": [0, 0, 0], "fov_y": 40, "resolution": [32, 24]},
  "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}, "panel": {"type": "emitter", "radiance": [2, 2, 2]}},
  "objects": [{"name": "floor", "material": "grey", "mesh": {"quad": [[-3, 0, -3], [-3, 0, 3], [3, 0, 3], [3, 0, -3]]}},
              {"name": "panel", "material": "panel", "mesh": {"quad": [[1, 2, -1], [2, 2, -1], [2, 2, 1], [1, 2, 1]]}}],
  "lights": [{"name": "bulb", "type": "point", "position": [0, 2, 0], "intensity": [3, 3, 3])" +
           lightExtra + R"(},
             {"name": "down", "type": "luminaire", "file": "luminaires/downlight.ies", "position": [-1, 2.5, 0], "direction": [0, -1, 0]})" +
           (withSun ? R"(,
             {"name": "sun", "type": "sun", "illuminance": 50000, "direction": [0, -1, 0]})" : "") +
           "]" + extra + "}\n";
}

Scene parse(const std::string& json) { return parseScene(json, kResources + "/scenes/case.json"); }

std::string rejection(const std::string& json) {
    try {
        parse(json);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(accepted)";
}


bool writeFile(const QString& path, const std::string& text) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text.data(), qint64(text.size())) == qint64(text.size());
}

GridResult computeGrid(const SceneSnapshot& scene, const std::vector<V3d>& points) {
    const RenderScene renderScene(sceneAsRendered(scene), 8, 8);
    GridSettings settings;
    settings.targetRelativeError = 1.0;  // met at once: both grids stop after minPasses, alike
    settings.seed = 7;
    TaskSystem tasks(0);
    GridResult result;
    auto job = tasks.submit(
        [&](TaskContext& ctx) { result = computeGridIlluminance(renderScene, points, V3d(0, 1, 0), settings, ctx); });
    job->wait();
    job->rethrowIfFailed();
    return result;
}

}  // namespace

class TestStandards : public QObject {
    Q_OBJECT

private slots:
    void roundTripsTheDesignKeys();
    void rejectsBadDesignKeys_data();
    void rejectsBadDesignKeys();
    void maintenanceFactorScalesElectricLightOnly();
    void maintainedGridIsTheFactorTimesTheNewOne();
    void luminaireFilesKeepOpeningWattsAndRa();
    void checksRequirementsWithMargins();
    void edition2021EntriesAsTheSourcesStateThem();
    void checks2021Figures();
    void modellingRatioIsGuidance();
    void standardsCommandListsAnEdition();
    void gridCommandChecksATaskArea();
};

void TestStandards::roundTripsTheDesignKeys() {
    const std::string json = sceneJson(
        R"(, "maintenance_factor": {"llmf": 0.9, "lsf": 1, "lmf": 0.95, "rsmf": 0.94},
  "task_areas": [{"name": "desk", "corner": [-1, 0.8, 1], "u": [2, 0, 0], "v": [0, 0, -2], "spacing": 0.25,
                  "activity": "5.26.2", "observers": [{"position": [0, 1.2, 2.5], "view": [0, 0, -1]}]},
                 {"name": "aisle", "corner": [-3, 0, 3], "u": [6, 0, 0], "v": [0, 0, -6]}],
  "project": {"name": "Test hall", "client": "Lucerna \"QA\"", "designer": "R. Tester", "notes": "two lines\nof notes"},
  "lighting_standard": "EN 12464-1:2011")",
        R"(, "maintenance_factor": 0.8)");
    std::string withArea = json;
    const std::string file = R"("file": "luminaires/downlight.ies",)";
    withArea.replace(withArea.find(file), file.size(), file + R"( "luminous_area": [0.2, 0.6], "maintenance_factor": {"lmf": 0.7},)");
    const Scene s = parse(withArea);
    QCOMPARE(s.lights[0].maintenance->factor(), 0.8);
    QCOMPARE(s.lights[1].maintenance->factor(), 0.7);
    QVERIFY(!s.lights[2].maintenance);
    QVERIFY(std::abs(s.maintenance->factor() - 0.9 * 0.95 * 0.94) < 1e-15);
    QCOMPARE(*s.lights[1].luminaire->luminousAreaM, V2d(0.2, 0.6));
    QCOMPARE(int(s.taskAreas.size()), 2);
    QCOMPARE(s.taskAreas[0].activity, std::string("5.26.2"));
    QCOMPARE(*s.taskAreas[0].grid.spacingMeters, 0.25);
    QCOMPARE(int(s.taskAreas[0].observers.size()), 1);
    QVERIFY(s.taskAreas[1].activity.empty() && s.taskAreas[1].observers.empty());
    QCOMPARE(s.project->client, std::string("Lucerna \"QA\""));
    QVERIFY(s.lightingStandard == StandardEdition::En12464_2011);
    QVERIFY(lightingStandardOf(s) == StandardEdition::En12464_2011);
    const std::string text = saveSceneToString(s);
    const Scene back = parse(text);
    QVERIFY(back == s);
    QCOMPARE(saveSceneToString(back), text);
    QVERIFY(text.find(R"("maintenance_factor": {"llmf": 0.9, "lsf": 1, "lmf": 0.95, "rsmf": 0.94})") != std::string::npos);
    QVERIFY(text.find(R"("luminous_area": [0.2, 0.6])") != std::string::npos);
    QVERIFY(text.find(R"("lighting_standard": "EN 12464-1:2011")") != std::string::npos);
    // The default edition given is written back as given; absent, it is 2021 and not written.
    const Scene given2021 = parse(sceneJson(R"(, "lighting_standard": "EN 12464-1:2021")"));
    QVERIFY(given2021.lightingStandard == StandardEdition::En12464_2021);
    QVERIFY(saveSceneToString(given2021).find(R"("lighting_standard": "EN 12464-1:2021")") != std::string::npos);
    QVERIFY(parse(saveSceneToString(given2021)) == given2021);
    // A scene without the keys writes none of them.
    const Scene bare = parse(sceneJson());
    QVERIFY(!bare.lightingStandard);
    QVERIFY(lightingStandardOf(bare) == StandardEdition::En12464_2021);
    const std::string plain = saveSceneToString(bare);
    for (const char* key : {"maintenance_factor", "task_areas", "project", "luminous_area", "lighting_standard"})
        QVERIFY2(plain.find(key) == std::string::npos, key);
}

void TestStandards::rejectsBadDesignKeys_data() {
    QTest::addColumn<QString>("json");
    QTest::addColumn<QString>("expected");
    const auto row = [](const char* name, const std::string& json, const char* expected) {
        QTest::newRow(name) << QString::fromStdString(json) << QString(expected);
    };
    row("factor 0", sceneJson(R"(, "maintenance_factor": 0)"), "maintenance_factor: must be in (0, 1], got 0");
    row("factor above 1", sceneJson({}, R"(, "maintenance_factor": 1.2)"), "lights[0].maintenance_factor: must be in (0, 1], got 1.2");
    row("factor a string", sceneJson(R"(, "maintenance_factor": "0.8")"), "maintenance_factor: expected a number or an object, got a string");
    row("factor empty", sceneJson(R"(, "maintenance_factor": {})"), "maintenance_factor: give at least one of llmf, lsf, lmf, rsmf");
    row("factor unknown", sceneJson(R"(, "maintenance_factor": {"mf": 0.8})"), "maintenance_factor.mf: unknown key");
    row("factor llmf 2", sceneJson(R"(, "maintenance_factor": {"llmf": 2})"), "maintenance_factor.llmf: must be in (0, 1], got 2");
    std::string sun = sceneJson();
    sun.replace(sun.find(R"("illuminance": 50000)"), 20, R"("illuminance": 50000, "maintenance_factor": 0.8)");
    row("factor on the sun", sun, "lights[2].maintenance_factor: unknown key for a sun light");
    std::string area = sceneJson();
    const std::string file = R"("file": "luminaires/downlight.ies",)";
    area.replace(area.find(file), file.size(), file + R"( "luminous_area": [0, 0.6],)");
    row("luminous area 0", area, "lights[1].luminous_area[0]: must be in (0, 1000] m, got 0");
    const std::string rect = R"("corner": [0, 0, 0], "u": [1, 0, 0], "v": [0, 0, 1])";
    row("activity unknown", sceneJson(R"(, "task_areas": [{"name": "a", )" + rect + R"(, "activity": "9.9"}])"),
        "task_areas[0].activity: unknown activity \"9.9\"");
    row("edges skew", sceneJson(R"(, "task_areas": [{"name": "a", "corner": [0, 0, 0], "u": [1, 0, 0], "v": [0.1, 0, 1]}])"),
        "task_areas[0].v: u and v must be perpendicular");
    row("same name", sceneJson(R"(, "task_areas": [{"name": "a", )" + rect + R"(}, {"name": "a", )" + rect + "}]"),
        "task_areas[1].name: another task area is already named \"a\"");
    row("observer view 0", sceneJson(R"(, "task_areas": [{"name": "a", )" + rect +
                                     R"(, "observers": [{"position": [0, 1.2, 0], "view": [0, 0, 0]}]}])"),
        "task_areas[0].observers[0].view: direction must be non-zero");
    row("project key", sceneJson(R"(, "project": {"title": "x"})"), "project.title: unknown key");
    row("edition unknown", sceneJson(R"(, "lighting_standard": "EN 12464-1:2002")"),
        R"(lighting_standard: unknown edition "EN 12464-1:2002" (expected "EN 12464-1:2021" or "EN 12464-1:2011"))");
    row("edition a year", sceneJson(R"(, "lighting_standard": 2021)"), "lighting_standard: expected a string, got a number");
}

void TestStandards::rejectsBadDesignKeys() {
    QFETCH(QString, json);
    QFETCH(QString, expected);
    const QString message = QString::fromStdString(rejection(json.toStdString()));
    QVERIFY2(message.contains(expected), qPrintable(message));
    QVERIFY2(!message.contains('\n'), qPrintable(message));
}

void TestStandards::maintenanceFactorScalesElectricLightOnly() {
    const Scene newScene = parse(sceneJson());
    QVERIFY(!maintenanceRange(newScene).maintained());
    QCOMPARE(describeMaintenance(maintenanceRange(newScene)), std::string("values of the new installation (no maintenance factor)"));
    const SceneSnapshot same = std::make_shared<const Scene>(newScene);
    QCOMPARE(sceneAsRendered(same), same);  // nothing to scale: the same snapshot

    const Scene maintained = parse(sceneJson(R"(, "maintenance_factor": 0.8)", R"(, "maintenance_factor": 0.5)"));
    const MaintenanceRange range = maintenanceRange(maintained);
    QCOMPARE(range.lowest, 0.5);
    QCOMPARE(range.highest, 0.8);
    QCOMPARE(describeMaintenance(range), std::string("maintained values (maintenance factors 0.50 to 0.80)"));
    const SceneSnapshot rendered = sceneAsRendered(std::make_shared<const Scene>(maintained));
    QCOMPARE(rendered->lights[0].intensity.x, 1.5);               // its own factor replaces the scene's
    QVERIFY(std::abs(luminaireFlux(rendered->lights[1]) / luminaireFlux(maintained.lights[1]) - 0.8) < 1e-12);
    QCOMPARE(rendered->lights[2].sun->illuminanceLux, 50000.0);  // daylight is not maintained
    QCOMPARE(rendered->findMaterial("panel")->radiance.x, 1.6);  // emitters take the scene's
    QCOMPARE(rendered->findMaterial("grey")->albedo.x, 0.5);
    QCOMPARE(maintenanceFactor(maintained, maintained.lights[2]), 1.0);
    Scene daylit = parse(sceneJson());
    for (Light& l : daylit.lights) l.on = l.type == LightType::Sun;
    daylit.objects.pop_back();  // the emitter panel
    QCOMPARE(describeMaintenance(maintenanceRange(daylit)), std::string("daylight only (no electric light to maintain)"));
    // The lux view's legend says which values it shows; luminance has no such note.
    DisplaySettings lux;
    lux.falseColour = true;
    lux.quantity = FalseColourQuantity::Illuminance;
    lux.illuminanceNote = "MF 0.80";
    QCOMPARE(luminanceLegend(lux)->unit, QString("lx, MF 0.80"));
    lux.quantity = FalseColourQuantity::Luminance;
    QCOMPARE(luminanceLegend(lux)->unit, QString("cd/m\u00b2"));
    // UGR's scene: the new installation.
    QVERIFY(!maintenanceRange(withoutMaintenance(maintained)).maintained());
}

void TestStandards::maintainedGridIsTheFactorTimesTheNewOne() {
    // No daylight here, so that one factor scales everything that lights the grid.
    const SceneSnapshot newScene = std::make_shared<const Scene>(parse(sceneJson({}, {}, false)));
    Scene m = *newScene;
    m.maintenance = MaintenanceFactor{0.8, {}, {}, {}, {}};
    const SceneSnapshot maintained = std::make_shared<const Scene>(m);
    const std::vector<V3d> points{{-2, 0.8, -2}, {0, 0.8, 0}, {1.5, 0.8, 0}, {2, 0.8, 2}};
    const GridResult a = computeGrid(newScene, points), b = computeGrid(maintained, points);
    QCOMPARE(a.passes, b.passes);
    for (size_t i = 0; i < points.size(); ++i) {
        QVERIFY(a.lux[i] > 1);
        QVERIFY2(std::abs(b.lux[i] / (0.8 * a.lux[i]) - 1) < 1e-5,
                 qPrintable(QString("point %1: %2 lx maintained, %3 lx new").arg(i).arg(b.lux[i]).arg(a.lux[i])));
    }
}

void TestStandards::luminaireFilesKeepOpeningWattsAndRa() {
    // IES in feet (units type 1): 2 ft x 4 ft, 0.5 ft high, 38 W; a round opening in metres.
    const std::string ies = "IESNA:LM-63-2002\n[LUMINAIRE] panel\nTILT=NONE\n1 3000 1 3 1 1 1 2 4 0.5\n1 1 38\n"
                            "0 45 90\n0\n1000 700 0\n";
    const GoniometricDistribution d = parseIes(ies, "panel.ies");
    QVERIFY(std::abs(d.luminous.widthM - 0.6096) < 1e-12 && std::abs(d.luminous.lengthM - 1.2192) < 1e-12);
    QVERIFY(std::abs(d.luminous.heightsM[2] - 0.1524) < 1e-12 && !d.luminous.elliptical && d.luminous.stated());
    QCOMPARE(*d.inputWatts, 38.0);
    QVERIFY(!d.colourRenderingIndex);
    const std::string round = "IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 2 1 1 2 -0.2 -0.2 0\n1 1 0\n0 90\n0\n100 0\n";
    const GoniometricDistribution r = parseIes(round, "round.ies");
    QVERIFY(r.luminous.elliptical && r.luminous.widthM == 0.2 && r.luminous.lengthM == 0.2);
    QVERIFY(!r.inputWatts);  // 0 W: not stated

    // The bundled EULUMDAT office luminaire states its luminous area, wattage and Ra.
    const GoniometricDistribution ldt = loadLuminaireFile(kResources + "/scenes/luminaires/office_linear.ldt");
    QVERIFY2(ldt.luminous.stated(), "office_linear.ldt states a luminous area");
    QVERIFY(ldt.inputWatts && *ldt.inputWatts > 0);
    QVERIFY(ldt.colourRenderingIndex && *ldt.colourRenderingIndex >= 80);
}

void TestStandards::checksRequirementsWithMargins() {
    const ActivityRequirement* writing = findActivity("5.26.2");
    QVERIFY(writing);
    QCOMPARE(writing->maintainedLux, 500.0);
    QCOMPARE(writing->ugrLimit, 19.0);
    QVERIFY(!findActivity("5.26"));
    // Error bars of 10 lx at every point: Eavg 465 +- 10, Emin 300 +- 10, U0 0.645 +- 0.035.
    TaskAreaFigures f;
    const auto withBars = [&](const std::vector<double>& lux, double bar) {
        f.grid = gridStatistics(lux);
        f.gridErrors = gridErrorBars(f.grid, lux, std::vector<double>(lux.size(), bar));
    };
    withBars({520, 480, 560, 300}, 10);
    QCOMPARE(f.gridErrors->average, 10.0);
    QCOMPARE(f.gridErrors->minimum, 10.0);
    QVERIFY(std::abs(f.gridErrors->uniformity - 300.0 / 465 * (10.0 / 300 + 10.0 / 465)) < 1e-12);
    f.maintainedValues = true;
    f.worstUgr = 19.4;
    f.worstUgrError = 0.1;
    const std::vector<RequirementCheck> checks = checkRequirements(*writing, f);
    QCOMPARE(int(checks.size()), 4);
    QCOMPARE(checks[0].describe(), std::string("Em 465 lx +- 10 lx >= 500 lx: not met (margin -35 lx, -7.0%)"));
    QCOMPARE(checks[1].describe(), std::string("U0 0.65 +- 0.04 >= 0.60: met (margin +0.05)"));
    QCOMPARE(checks[2].describe(), std::string("UGR 19.4 +- 0.1 <= 19.0: not met (margin -0.4)"));
    QCOMPARE(checks[3].describe(), std::string("Ra not stated (>= 80 required)"));
    QCOMPARE(int(checks[3].outcome), int(CheckOutcome::NotStated));

    // A tie within the error bar is borderline, never met; an exact figure's tie is met.
    f.worstUgr = 19.0;
    f.colourRendering = 80;
    withBars({505, 495}, 8);  // Eavg 500 +- 8
    std::vector<RequirementCheck> tie = checkRequirements(*writing, f);
    QCOMPARE(tie[0].describe(), std::string("Em 500 lx +- 8 lx >= 500 lx: borderline (margin +0 lx, +0.0%, within the error bar)"));
    QCOMPARE(int(tie[0].outcome), int(CheckOutcome::Borderline));
    QCOMPARE(tie[2].describe(), std::string("UGR 19.0 +- 0.1 <= 19.0: borderline (margin +0.0, within the error bar)"));
    QCOMPARE(int(tie[3].outcome), int(CheckOutcome::Met));
    withBars({515, 505}, 8);  // Eavg 510 +- 8: the margin exceeds the bar
    QCOMPARE(int(checkRequirements(*writing, f)[0].outcome), int(CheckOutcome::Met));
    withBars({487, 487}, 8);  // 13 lx short, more than the bar
    QCOMPARE(int(checkRequirements(*writing, f)[0].outcome), int(CheckOutcome::NotMet));

    // EN 12464-1's Em is maintained: values of a new installation are not checked against it,
    // however far above; nor is a figure without an error bar.
    withBars({900, 880}, 5);
    f.maintainedValues = false;
    const std::vector<RequirementCheck> fresh = checkRequirements(*writing, f);
    QCOMPARE(int(fresh[0].outcome), int(CheckOutcome::NotChecked));
    QVERIFY2(fresh[0].describe().find("not checked: no maintenance factor") != std::string::npos, fresh[0].describe().c_str());
    QCOMPARE(int(fresh[1].outcome), int(CheckOutcome::Met));  // U0 is a ratio: the factor cancels
    f.maintainedValues = true;
    f.grid = gridStatistics({600, 560});
    f.gridErrors.reset();
    f.worstUgr.reset();
    f.colourRendering = 85;
    const std::vector<RequirementCheck> better = checkRequirements(*writing, f);
    QCOMPARE(better[0].describe(), std::string("Em 580 lx >= 500 lx: not checked: error bar unknown"));
    QCOMPARE(better[2].describe(), std::string("UGR not computed (<= 19.0 required)"));
    QCOMPARE(better[3].describe(), std::string("Ra 85 >= 80: met (margin +5)"));
}

void TestStandards::edition2021EntriesAsTheSourcesStateThem() {
    // Each bundled 2021 entry, figure by figure, as the source named beside it in
    // lighting_standards.cpp states it; Ez, walls and ceiling with the table's U0 0.10.
    struct Stated {
        const char* reference;
        double em, emU, ugr, u0, ra, ez, wall, ceiling;
    };
    const Stated stated[] = {{"5.26.2", 500, 1000, 19, 0.60, 80, 150, 150, 100},
                             {"5.26.5", 500, 1000, 19, 0.60, 80, 150, 150, 100},
                             {"5.36.17", 200, 300, 19, 0.60, 80, 0, 0, 0}};
    QCOMPARE(int(en12464Activities(StandardEdition::En12464_2021).size()), int(std::size(stated)));
    for (const Stated& e : stated) {
        const ActivityRequirement* a = findActivity(e.reference, StandardEdition::En12464_2021);
        QVERIFY2(a && a->edition == StandardEdition::En12464_2021, e.reference);
        QCOMPARE(a->maintainedLux, e.em);
        QCOMPARE(a->modifiedLux, e.emU);
        QCOMPARE(a->ugrLimit, e.ugr);
        QCOMPARE(a->uniformity, e.u0);
        QCOMPARE(a->colourRendering, e.ra);
        QCOMPARE(a->cylindricalLux, e.ez);
        QCOMPARE(a->wallLux, e.wall);
        QCOMPARE(a->ceilingLux, e.ceiling);
        for (auto [lux, u0] : {std::pair(a->cylindricalLux, a->cylindricalUniformity), std::pair(a->wallLux, a->wallUniformity),
                               std::pair(a->ceilingLux, a->ceilingUniformity)})
            QCOMPARE(u0, lux > 0 ? 0.10 : 0.0);
        // Keyed by the 2011 number of the same activity: same area and name.
        const ActivityRequirement* old = findActivity(e.reference, StandardEdition::En12464_2011);
        QVERIFY2(old && old->edition == StandardEdition::En12464_2011 && old != a, e.reference);
        QCOMPARE(std::string(old->area), std::string(a->area));
        QCOMPARE(std::string(old->activity), std::string(a->activity));
    }
    // Every other activity falls back to its 2011 entry, which says so; unknown ones stay unknown.
    const ActivityRequirement* filing = findActivity("5.26.1", StandardEdition::En12464_2021);
    QVERIFY(filing && filing->edition == StandardEdition::En12464_2011 && filing == findActivity("5.26.1"));
    QVERIFY(!findActivity("5.26", StandardEdition::En12464_2021));
    // The edition's list: the 2011 references in order, 2021 entries where bundled.
    const std::vector<const ActivityRequirement*> list2021 = activitiesOf(StandardEdition::En12464_2021);
    const std::span<const ActivityRequirement> table2011 = en12464Activities(StandardEdition::En12464_2011);
    QCOMPARE(list2021.size(), table2011.size());
    int bundled = 0;
    for (size_t i = 0; i < list2021.size(); ++i) {
        QCOMPARE(std::string(list2021[i]->reference), std::string(table2011[i].reference));
        QVERIFY(list2021[i] == findActivity(table2011[i].reference, StandardEdition::En12464_2021));
        bundled += list2021[i]->edition == StandardEdition::En12464_2021;
        QVERIFY(activitiesOf(StandardEdition::En12464_2011)[i] == &table2011[i]);
    }
    QCOMPARE(bundled, int(std::size(stated)));

    // The requirement line names the edition, its additions, and a fallback.
    const ActivityRequirement* writing = findActivity("5.26.2", StandardEdition::En12464_2021);
    const std::string writing2021 =
        "EN 12464-1:2021 5.26.2, Offices: Writing, typing, reading, data processing: Em 500 lx (Em,u 1000 lx), U0 0.60, "
        "UGR_L 19, Ra 80, Ez 150 lx (U0 0.10), Ewall 150 lx (U0 0.10), Eceiling 100 lx (U0 0.10)";
    QCOMPARE(describeRequirement(*writing, StandardEdition::En12464_2021), writing2021);
    QCOMPARE(describeRequirement(*writing), writing2021);
    QCOMPARE(describeRequirement(*findActivity("5.36.17", StandardEdition::En12464_2021)),
             std::string("EN 12464-1:2021 5.36.17, Educational buildings: Libraries: bookshelves: Em 200 lx (Em,u 300 lx), "
                         "U0 0.60, UGR_L 19, Ra 80"));
    QCOMPARE(describeRequirement(*findActivity("5.26.2"), StandardEdition::En12464_2011),
             std::string("EN 12464-1:2011 5.26.2, Offices: Writing, typing, reading, data processing: Em 500 lx, U0 0.60, "
                         "UGR_L 19, Ra 80"));
    QCOMPARE(describeRequirement(*filing, StandardEdition::En12464_2021),
             std::string("EN 12464-1:2011 5.26.1, Offices: Filing, copying, etc.: Em 300 lx, U0 0.40, UGR_L 19, Ra 80 "
                         "(EN 12464-1:2021 asked; its table here lacks this activity)"));
    QVERIFY(standardEditionFromName("EN 12464-1:2021") == StandardEdition::En12464_2021);
    QVERIFY(!standardEditionFromName("EN 12464-1"));
}

void TestStandards::checks2021Figures() {
    const ActivityRequirement* writing = findActivity("5.26.2", StandardEdition::En12464_2021);
    const auto surface = [](const std::vector<double>& lux, double bar) {
        SurfaceIlluminance s;
        s.grid = gridStatistics(lux);
        s.errors = gridErrorBars(s.grid, lux, std::vector<double>(lux.size(), bar));
        return s;
    };
    TaskAreaFigures f;
    f.grid = gridStatistics({520, 500});
    f.gridErrors = gridErrorBars(f.grid, {520, 500}, {4, 4});
    f.colourRendering = 80;
    // Without any 2021 figure: each stated requirement listed, not computed.
    std::vector<RequirementCheck> c = checkRequirements(*writing, f);
    const char* order[] = {"Em", "U0", "UGR", "Ra", "Ez", "U0,z", "Ewall", "U0,wall", "Eceiling", "U0,ceiling"};
    QCOMPARE(int(c.size()), int(std::size(order)));
    for (size_t i = 0; i < c.size(); ++i) QCOMPARE(c[i].quantity, std::string(order[i]));
    QCOMPARE(c[4].describe(), std::string("Ez not computed (>= 150 lx required)"));
    QCOMPARE(c[5].describe(), std::string("U0,z not computed (>= 0.10 required)"));
    QCOMPARE(c[6].describe(), std::string("Ewall not computed (>= 150 lx required)"));
    QCOMPARE(c[9].describe(), std::string("U0,ceiling not computed (>= 0.10 required)"));
    QCOMPARE(int(c[4].outcome), int(CheckOutcome::NotStated));

    // Ez, walls and ceiling are maintained values: not checked on the new installation's, however
    // far above; their uniformities are ratios, checked.
    f.cylindrical = surface({400, 380}, 5);
    c = checkRequirements(*writing, f);
    QCOMPARE(int(c[4].outcome), int(CheckOutcome::NotChecked));
    QVERIFY2(c[4].describe().find("Ez 390 lx +- 5 lx >= 150 lx: not checked: no maintenance factor") == 0, c[4].describe().c_str());
    QCOMPARE(int(c[5].outcome), int(CheckOutcome::Met));

    // With a maintenance factor: a requirement within the error bar is borderline; beyond it,
    // met or not met.
    f.maintainedValues = true;
    f.cylindrical = surface({152, 148}, 5);  // 150 +- 5
    f.walls = surface({300, 30}, 2);         // 165 +- 2, U0 0.18 +- 0.01
    f.ceiling = surface({40, 60}, 3);        // 50 +- 3
    c = checkRequirements(*writing, f);
    QCOMPARE(c[4].describe(), std::string("Ez 150 lx +- 5 lx >= 150 lx: borderline (margin +0 lx, +0.0%, within the error bar)"));
    QCOMPARE(c[6].describe(), std::string("Ewall 165 lx +- 2 lx >= 150 lx: met (margin +15 lx, +10.0%)"));
    QCOMPARE(c[7].describe(), std::string("U0,wall 0.18 +- 0.01 >= 0.10: met (margin +0.08)"));
    QCOMPARE(c[8].describe(), std::string("Eceiling 50 lx +- 3 lx >= 100 lx: not met (margin -50 lx, -50.0%)"));
    QCOMPARE(int(c[8].outcome), int(CheckOutcome::NotMet));
    // A figure whose method backs no error bar is not judged.
    f.ceiling->errors.reset();
    QCOMPARE(checkRequirements(*writing, f)[8].describe(), std::string("Eceiling 50 lx >= 100 lx: not checked: error bar unknown"));

    // An entry without the 2021 figures checks the four of old, whatever was computed.
    QCOMPARE(int(checkRequirements(*findActivity("5.26.1", StandardEdition::En12464_2021), f).size()), 4);
    QCOMPARE(int(checkRequirements(*findActivity("5.36.17", StandardEdition::En12464_2021), f).size()), 4);
}

void TestStandards::modellingRatioIsGuidance() {
    TaskAreaFigures f;
    f.grid = gridStatistics({500, 500});
    QVERIFY(!modellingRatio(f));  // no Ez
    const auto withEz = [&](double ez) {
        SurfaceIlluminance s;
        s.grid = gridStatistics({ez, ez});
        f.cylindrical = s;
        return modellingRatio(f);
    };
    QCOMPARE(describeModelling(*withEz(210)), std::string("modelling Ez/Eh 0.42 (guidance 0.30 to 0.60: within)"));
    QCOMPARE(describeModelling(*withEz(100)), std::string("modelling Ez/Eh 0.20 (guidance 0.30 to 0.60: below: flat)"));
    QCOMPARE(describeModelling(*withEz(350)), std::string("modelling Ez/Eh 0.70 (guidance 0.30 to 0.60: above: harsh)"));
    QVERIFY(describeModelling(*withEz(150)).find(": within)") != std::string::npos);  // the bounds are within
    QVERIFY(describeModelling(*withEz(300)).find(": within)") != std::string::npos);
    f.grid = gridStatistics({0, 0});
    QVERIFY(!modellingRatio(f));  // Eh 0
}

void TestStandards::standardsCommandListsAnEdition() {
    const Run latest = runLucerna({"standards"});
    QVERIFY2(latest.exitCode == 0, qPrintable(latest.err));
    QVERIFY2(latest.out.startsWith("EN 12464-1:2021 (a selection)"), qPrintable(latest.out));
    QVERIFY2(latest.out.contains("\n5.26.2  Offices: Writing, typing, reading, data processing; Em 500, UGR_L 19, U0 0.60, "
                                 "Ra 80; Em,u 1000; Ez 150 (0.10), walls 150 (0.10), ceiling 100 (0.10)\n"),
             qPrintable(latest.out));
    QVERIFY2(latest.out.contains("\n5.36.17  Educational buildings: Libraries: bookshelves; Em 200, UGR_L 19, U0 0.60, Ra 80; "
                                 "Em,u 300; Ez -, walls -, ceiling -\n"),
             qPrintable(latest.out));
    QVERIFY2(latest.out.contains("\n5.26.1  Offices: Filing, copying, etc.; Em 300, UGR_L 19, U0 0.40, Ra 80; 2011 entry\n"),
             qPrintable(latest.out));
    QCOMPARE(int(latest.out.count("2011 entry\n")),
             int(en12464Activities(StandardEdition::En12464_2011).size() - en12464Activities(StandardEdition::En12464_2021).size()));
    const Run old = runLucerna({"standards", "--edition", "2011"});
    QVERIFY2(old.exitCode == 0, qPrintable(old.err));
    QVERIFY2(old.out.startsWith("EN 12464-1:2011 (a selection)"), qPrintable(old.out));
    QVERIFY2(old.out.contains("\n5.26.2  Offices: Writing, typing, reading, data processing; Em 500, UGR_L 19, U0 0.60, Ra 80\n"),
             qPrintable(old.out));
    QVERIFY(!old.out.contains("Em,u") && !old.out.contains("2011 entry"));
    QCOMPARE(runLucerna({"standards", "--edition", "2021"}).out, latest.out);
    const Run bad = runLucerna({"standards", "--edition", "2002"});
    QCOMPARE(bad.exitCode, 2);
    QVERIFY2(bad.err.contains("--edition: expected 2011 or 2021, got '2002'"), qPrintable(bad.err));
    QCOMPARE(runLucerna({"standards", "2021"}).exitCode, 2);
}

void TestStandards::gridCommandChecksATaskArea() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir("luminaires"));
    QVERIFY(QFile::copy(QString::fromStdString(kResources + "/scenes/luminaires/downlight.ies"), dir.filePath("luminaires/downlight.ies")));
    const QString scene = dir.filePath("hall.json");
    QVERIFY(writeFile(scene, sceneJson(R"(, "maintenance_factor": 0.8,
  "task_areas": [{"name": "desk", "corner": [-1, 0.8, 1], "u": [2, 0, 0], "v": [0, 0, -2], "spacing": 0.5, "activity": "5.26.2"}])")));
    // --horizontal-only: the 2021 figures are test_grid_task_area's.
    const Run r = runLucerna({"grid", scene, "--task-area", "desk", "--error", "0.2", "--seed", "3", "--horizontal-only"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY2(r.out.contains("grid 'desk': 4 x 4 points"), qPrintable(r.out));
    QVERIFY2(r.out.contains("maintained values (maintenance factor 0.80)"), qPrintable(r.out));
    // No lighting_standard: the 2021 edition, whose entry adds Em,u and the Ez, wall and ceiling
    // requirements, here not computed (--horizontal-only).
    QVERIFY2(r.out.contains("EN 12464-1:2021 5.26.2, Offices: Writing, typing, reading, data processing: Em 500 lx "
                            "(Em,u 1000 lx)"),
             qPrintable(r.out));
    QVERIFY2(r.out.contains("  Ez not computed (>= 150 lx required)"), qPrintable(r.out));
    // The check's Em is the printed Eavg, to the lux, and its verdict follows.
    const QRegularExpressionMatch eavg = QRegularExpression("Eavg ([0-9.]+) lx").match(r.out);
    const QRegularExpressionMatch em =
        QRegularExpression("\n  Em ([0-9]+) lx \\+- ([0-9.]+) lx >= 500 lx: (met|borderline|not met) \\(margin ").match(r.out);
    QVERIFY2(eavg.hasMatch() && em.hasMatch(), qPrintable(r.out));
    QVERIFY(std::abs(decimal(em.captured(1)) - decimal(eavg.captured(1))) <= 0.55);
    const double achieved = decimal(eavg.captured(1)), bar = decimal(em.captured(2));
    QVERIFY(bar > 0);
    QCOMPARE(em.captured(3), QString(achieved - 500 > bar + 0.5   ? "met"
                                     : 500 - achieved > bar + 0.5 ? "not met"
                                                                  : em.captured(3)));  // near the edge: rounding decides
    QVERIFY2(r.out.contains("  Ra not stated (>= 80 required)"), qPrintable(r.out));

    const Run missing = runLucerna({"grid", scene, "--task-area", "bench"});
    QCOMPARE(missing.exitCode, 2);
    QVERIFY2(missing.err.contains("--task-area: the scene has no task area 'bench' (it has: desk)"), qPrintable(missing.err));
    const Run both = runLucerna({"grid", scene, "--task-area", "desk", "--work-plane", "0.8"});
    QCOMPARE(both.exitCode, 2);
    QVERIFY2(both.err.contains("give one of --work-plane"), qPrintable(both.err));
}

QTEST_GUILESS_MAIN(TestStandards)
#include "test_standards.moc"
