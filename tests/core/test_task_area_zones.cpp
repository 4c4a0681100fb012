// EN 12464-1's zones around a task area (README, "Task areas"): the scene keys surrounding_m and
// background_m parsed strictly and written back exactly; the requirements that follow from the
// task area's Em; the bands' points (inside the band, covering it, clipped to the room); and the
// plan rectangle the window edits a task area by.

#include "core/photometry/plan_rectangle.h"
#include "core/photometry/surrounding_zones.h"
#include "core/scene/scene_io.h"

#include <QTest>

#include <cmath>

using namespace lucerna;

namespace {
// A 10 m x 10 m floor from (0, 0, 0) to (10, 0, 10); `areas` goes into "task_areas".
std::string sceneJson(const std::string& areas) {
    return R"({"lucerna": 1,
  "camera": {"position": [5, 2, 12], "target": [5, 0, 5], "fov_y": 40, "resolution": [32, 24]},
  "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "objects": [{"name": "floor", "material": "grey", "mesh": {"quad": [[0, 0, 0], [0, 0, 10], [10, 0, 10], [10, 0, 0]]}}],
  "task_areas": [)" + areas + "]}\n";
}

Scene parse(const std::string& json) { return parseScene(json, std::string(LUCERNA_RESOURCE_DIR) + "/scenes/case.json"); }

std::string rejection(const std::string& json) {
    try {
        parse(json);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(accepted)";
}

// Whether p lies in the rectangle of g (in its plane), with a tolerance.
bool inside(const CalculationGrid& g, const V3d& p, double eps = 1e-9) {
    const V3d d = p - g.corner;
    const double s = d.dot(g.edgeU) / g.edgeU.dot(g.edgeU), t = d.dot(g.edgeV) / g.edgeV.dot(g.edgeV);
    return s >= -eps && s <= 1 + eps && t >= -eps && t <= 1 + eps;
}

double stripsArea(const ZoneGrid& z) {
    double a = 0;
    for (const CalculationGrid& g : z.strips) a += g.edgeU.cross(g.edgeV).length();
    return a;
}
}  // namespace

class TestTaskAreaZones : public QObject {
    Q_OBJECT
private slots:
    void keysRoundTrip() {
        const std::string json = sceneJson(
            R"({"name": "desk", "corner": [2, 0.75, 3], "u": [2, 0, 0], "v": [0, 0, -1], "activity": "5.26.2",
                "surrounding_m": 0.5, "background_m": 3},
               {"name": "bench", "corner": [6, 0.9, 8], "u": [1.2, 0, 0], "v": [0, 0, -0.6], "surrounding_m": 0.75},
               {"name": "aisle", "corner": [0, 0, 10], "u": [10, 0, 0], "v": [0, 0, -10]})");
        const Scene s = parse(json);
        QCOMPARE(s.taskAreas.size(), size_t(3));
        QCOMPARE(*s.taskAreas[0].surroundingMeters, 0.5);
        QCOMPARE(*s.taskAreas[0].backgroundMeters, 3.0);
        QCOMPARE(*s.taskAreas[1].surroundingMeters, 0.75);
        QVERIFY(!s.taskAreas[1].backgroundMeters);
        QVERIFY(!s.taskAreas[2].surroundingMeters && !s.taskAreas[2].backgroundMeters);
        const std::string text = saveSceneToString(s);
        QVERIFY2(text.find(R"("activity": "5.26.2", "surrounding_m": 0.5, "background_m": 3)") != std::string::npos, text.c_str());
        QVERIFY(text.find(R"("surrounding_m": 0.75})") != std::string::npos);
        const Scene back = parse(text);
        QVERIFY(back == s);
        QCOMPARE(saveSceneToString(back), text);
        // A width that is not the same is a different area (the document's edits rely on it).
        Scene other = s;
        other.taskAreas[1].surroundingMeters = 0.8;
        QVERIFY(!(other == s));
        other = s;
        other.taskAreas[0].backgroundMeters.reset();
        QVERIFY(!(other == s));
        // Without zones, no keys written.
        const std::string plain = saveSceneToString(parse(sceneJson(R"({"name": "a", "corner": [0, 0, 1], "u": [1, 0, 0], "v": [0, 0, -1]})")));
        QVERIFY(plain.find("surrounding_m") == std::string::npos && plain.find("background_m") == std::string::npos);
    }

    void keysRejected_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<QString>("expected");
        QTest::newRow("narrow zone") << R"("surrounding_m": 0.3)" << "task_areas[0].surrounding_m: must be in [0.5, 1000] m, got 0.3";
        QTest::newRow("zone a string") << R"("surrounding_m": "0.5")" << "task_areas[0].surrounding_m: expected a number";
        QTest::newRow("narrow background") << R"("surrounding_m": 0.5, "background_m": 2)"
                                           << "task_areas[0].background_m: must be in [3, 1000] m, got 2";
        QTest::newRow("background alone") << R"("background_m": 3)"
                                          << "task_areas[0].background_m: needs surrounding_m (the background area lies around the surrounding zone)";
        QTest::newRow("unknown key") << R"("surrounding": 0.5)" << "task_areas[0].surrounding: unknown key";
    }
    void keysRejected() {
        QFETCH(QString, keys);
        QFETCH(QString, expected);
        const std::string message = rejection(
            sceneJson(R"({"name": "a", "corner": [1, 0.8, 2], "u": [1, 0, 0], "v": [0, 0, -1], )" + keys.toStdString() + "}"));
        QVERIFY2(QString::fromStdString(message).contains(expected), message.c_str());
        QVERIFY2(message.find('\n') == std::string::npos, message.c_str());
    }

    // EN 12464-1:2011 table 1 and 4.3.3.
    void requirementsFollowTheTaskArea() {
        const std::pair<double, double> table[] = {{1000, 500}, {750, 500}, {500, 300}, {300, 200}, {200, 200},
                                                   {150, 150}, {100, 100}, {400, 200}, {250, 200}};
        for (const auto& [task, zone] : table) {
            QCOMPARE(surroundingZoneRequirement(task).maintainedLux, zone);
            QCOMPARE(surroundingZoneRequirement(task).uniformity, 0.40);
        }
        QCOMPARE(backgroundAreaRequirement(300).maintainedLux, 100.0);
        QCOMPARE(backgroundAreaRequirement(300).uniformity, 0.10);
        QCOMPARE(describeZoneRequirement("surrounding zone", 0.5, surroundingZoneRequirement(500)),
                 std::string("surrounding zone (0.5 m): Em 300 lx, U0 0.40"));
        // Checked as a task area's are: Em and U0 only, Em not without maintained values.
        TaskAreaFigures f;
        f.grid.average = 320;
        f.grid.uniformity = 0.5;
        f.gridErrors = GridErrorBars{5, 5, 0.02};
        f.maintainedValues = true;
        const std::vector<RequirementCheck> checks = checkZone({300, 0.4}, f);
        QCOMPARE(checks.size(), size_t(2));
        QCOMPARE(checks[0].outcome, CheckOutcome::Met);
        QCOMPARE(checks[1].outcome, CheckOutcome::Met);
        f.grid.average = 298;
        QCOMPARE(checkZone({300, 0.4}, f)[0].outcome, CheckOutcome::Borderline);
        f.maintainedValues = false;
        QCOMPARE(checkZone({300, 0.4}, f)[0].outcome, CheckOutcome::NotChecked);
    }

    // A 2 m x 1 m desk in the middle of a 10 m room: the band's strips cover exactly the band,
    // every point lies in the band and none in the desk, at EN 12464-1's spacing.
    void bandPointsLieInTheBand() {
        const V3d lo(0, 0, 0), hi(10, 3, 10);
        CalculationGrid desk;
        desk.corner = V3d(4, 0.75, 5);
        desk.edgeU = V3d(2, 0, 0);
        desk.edgeV = V3d(0, 0, -1);
        const ZoneGrid zone = zoneGrid(desk, 0, 0.5, 1.0, lo, hi);
        QCOMPARE(zone.strips.size(), size_t(4));
        QVERIFY(std::abs(stripsArea(zone) - (3 * 2 - 2 * 1)) < 1e-12);
        QCOMPARE(zone.spacingMeters, en12464Spacing(3));
        CalculationGrid outer = desk;
        outer.corner = desk.corner + V3d(-0.5, 0, 0.5);
        outer.edgeU = V3d(3, 0, 0);
        outer.edgeV = V3d(0, 0, -2);
        size_t expected = 0;
        for (const CalculationGrid& g : zone.strips) {
            QCOMPARE(g.normal(), desk.normal());
            expected += layoutGrid(g, 1.0).points.size();
        }
        QCOMPARE(zone.points.size(), expected);
        QVERIFY(zone.points.size() >= 4 * 2);  // at least two points across each strip's length
        for (const V3d& p : zone.points) {
            QVERIFY(inside(outer, p));
            QVERIFY(!inside(desk, p, -1e-9));
            QCOMPARE(p.y, 0.75);
        }
        // The background area around it, 3 m more: x 0.5..9.5, z 0.5..8.5, which the room holds.
        const ZoneGrid background = zoneGrid(desk, 0.5, 3, 1.0, lo, hi);
        const double outerW = 9, outerD = 8;
        QVERIFY2(std::abs(stripsArea(background) - (outerW * outerD - 3 * 2)) < 1e-9, qPrintable(QString::number(stripsArea(background))));
        for (const V3d& p : background.points) QVERIFY(!inside(outer, p, -1e-9) && p.x >= 0 && p.x <= 10 && p.z >= 0 && p.z <= 10);
        const auto outerRect = zoneOuterRectangle(desk, 0.5, 3, 1.0, lo, hi);
        QVERIFY(outerRect && std::abs(outerRect->edgeU.length() - outerW) < 1e-12 && std::abs(outerRect->edgeV.length() - outerD) < 1e-12);
    }

    // A desk against the wall at x = 0: no band on the wall's side; the given spacing is used.
    void bandClippedByTheRoom() {
        CalculationGrid desk;
        desk.corner = V3d(0, 0.75, 2);
        desk.edgeU = V3d(1.6, 0, 0);
        desk.edgeV = V3d(0, 0, -0.8);
        const ZoneGrid zone = zoneGrid(desk, 0, 0.5, 1.0, V3d(0, 0, 0), V3d(5, 3, 5), 0.1);
        QCOMPARE(zone.strips.size(), size_t(3));
        QVERIFY(std::abs(stripsArea(zone) - (2.1 * 1.8 - 1.6 * 0.8)) < 1e-12);
        QCOMPARE(zone.spacingMeters, 0.1);
        for (const V3d& p : zone.points) QVERIFY(p.x > 0);
        // A scene unit of a millimetre: the band is 500 units wide.
        CalculationGrid mm = desk;
        mm.corner = desk.corner * 1000;
        mm.edgeU = desk.edgeU * 1000;
        mm.edgeV = desk.edgeV * 1000;
        const ZoneGrid inMm = zoneGrid(mm, 0, 0.5, 0.001, V3d(0, 0, 0), V3d(5000, 3000, 5000), 0.1);
        QVERIFY(std::abs(stripsArea(inMm) - 1e6 * (2.1 * 1.8 - 1.6 * 0.8)) < 1e-3);
        QCOMPARE(inMm.points.size(), zone.points.size());
        // The background area there: x 0..5, z 0..5 less the surrounding zone's x 0..2.1, z 0.7..2.5.
        const ZoneGrid background = zoneGrid(desk, 0.5, 3, 1.0, V3d(0, 0, 0), V3d(5, 3, 5));
        QVERIFY2(std::abs(stripsArea(background) - (25 - 2.1 * 1.8)) < 1e-9, qPrintable(QString::number(stripsArea(background))));
        QCOMPARE(background.strips.size(), size_t(3));
        // The task area's keys: both bands, the background outside the surrounding zone.
        TaskArea area;
        area.grid = desk;
        area.surroundingMeters = 0.5;
        area.backgroundMeters = 3;
        const TaskAreaZones zones = taskAreaZones(area, 1.0, V3d(0, 0, 0), V3d(5, 3, 5));
        QVERIFY(zones.surrounding && zones.background);
        area.surroundingMeters.reset();
        QVERIFY(taskAreaZones(area, 1.0, V3d(0, 0, 0), V3d(5, 3, 5)).empty());
    }

    void planRectangles() {
        const PlanRectangle r{1, 2, 1.6, 0.8, 0.75};
        const CalculationGrid g = gridOfPlanRectangle(r);
        QCOMPARE(g.normal(), V3d(0, 1, 0));
        const PlanRectangle back = *planRectangle(g);  // to rounding (the far corner is a sum)
        QVERIFY(std::abs(back.x0 - r.x0) + std::abs(back.z0 - r.z0) + std::abs(back.width - r.width) +
                    std::abs(back.depth - r.depth) + std::abs(back.y - r.y) < 1e-12);
        // The same rectangle laid out the other way round, or facing down, reads the same.
        CalculationGrid turned;
        turned.corner = V3d(2.6, 0.75, 2.8);
        turned.edgeU = V3d(0, 0, -0.8);
        turned.edgeV = V3d(-1.6, 0, 0);
        QVERIFY(std::abs(planRectangle(turned)->x0 - 1) < 1e-12 && std::abs(planRectangle(turned)->depth - 0.8) < 1e-12);
        // On a wall, or turned in the plan: none.
        CalculationGrid wall;
        wall.corner = V3d(0, 0, 0);
        wall.edgeU = V3d(1, 0, 0);
        wall.edgeV = V3d(0, 1, 0);
        QVERIFY(!planRectangle(wall));
        CalculationGrid skew;
        skew.edgeU = V3d(1, 0, 1);
        skew.edgeV = V3d(-1, 0, 1);
        QVERIFY(!planRectangle(skew));
    }
};

QTEST_MAIN(TestTaskAreaZones)
#include "test_task_area_zones.moc"
