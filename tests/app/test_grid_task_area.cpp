// `lucerna grid --task-area` with EN 12464-1:2021's figures (README, "Task areas"): on a small
// room whose desk is an office activity (5.26.2: Ez 150 lx, walls 150 lx, ceiling 100 lx), it
// prints Ez at 1.2 m, the modelling ratio, the walls and the ceiling, their checks in the one
// list after Em's, and the surrounding zone's figures and checks; --horizontal-only computes
// none of them; --cylindrical computes Ez for an area without an activity (standing: 1.6 m);
// without a task area --cylindrical makes the points measure Ez. Bad combinations are one line.

#include "process_run.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <charconv>
#include <cmath>

using namespace lucerna::test;

namespace {

double decimal(const QString& text) {
    const std::string s = text.toStdString();
    double x = std::nan("");
    std::from_chars(s.data(), s.data() + s.size(), x);
    return x;
}

// A closed 3 x 2.8 x 3 m room, grey, lit by a point light under its ceiling; a desk with the
// office activity and a surrounding zone, a counter (standing, no activity). No
// lighting_standard: EN 12464-1:2021.
const char* kRoom = R"({"lucerna": 1,
  "camera": {"position": [1.5, 1.5, 2.9], "target": [1.5, 0.8, 0], "fov_y": 60, "resolution": [16, 16]},
  "materials": {"grey": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]}},
  "objects": [
    {"name": "floor", "material": "grey", "mesh": {"quad": [[0, 0, 0], [3, 0, 0], [3, 0, 3], [0, 0, 3]]}},
    {"name": "ceiling", "material": "grey", "mesh": {"quad": [[0, 2.8, 0], [0, 2.8, 3], [3, 2.8, 3], [3, 2.8, 0]]}},
    {"name": "wall 1", "material": "grey", "mesh": {"quad": [[0, 0, 0], [0, 0, 3], [0, 2.8, 3], [0, 2.8, 0]]}},
    {"name": "wall 2", "material": "grey", "mesh": {"quad": [[3, 0, 0], [3, 2.8, 0], [3, 2.8, 3], [3, 0, 3]]}},
    {"name": "wall 3", "material": "grey", "mesh": {"quad": [[0, 0, 0], [0, 2.8, 0], [3, 2.8, 0], [3, 0, 0]]}},
    {"name": "wall 4", "material": "grey", "mesh": {"quad": [[0, 0, 3], [3, 0, 3], [3, 2.8, 3], [0, 2.8, 3]]}}],
  "lights": [{"name": "bulb", "type": "point", "position": [1.5, 2.5, 1.5], "candela": 400}],
  "maintenance_factor": 0.8,
  "task_areas": [
    {"name": "desk", "corner": [1, 0.8, 2], "u": [1, 0, 0], "v": [0, 0, -1], "spacing": 0.5, "activity": "5.26.2",
     "surrounding_m": 0.5},
    {"name": "counter", "corner": [0.5, 0.9, 1], "u": [1, 0, 0], "v": [0, 0, -0.5], "spacing": 0.5, "posture": "standing"}]}
)";

QString writeRoom(const QTemporaryDir& dir) {
    const QString path = dir.filePath("room.json");
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(kRoom) < 0) return {};
    return path;
}

const QStringList kFast = {"--error", "0.1", "--seed", "3", "--threads", "2"};

}  // namespace

class TestGridTaskArea : public QObject {
    Q_OBJECT
private slots:
    void printsThe2021FiguresAndTheirChecks();
    void horizontalOnlyComputesNone();
    void cylindricalForAnAreaWithoutActivity();
    void cylindricalGridWithoutTaskArea();
    void refusesBadCombinations();
};

void TestGridTaskArea::printsThe2021FiguresAndTheirChecks() {
    QTemporaryDir dir;
    const QString scene = writeRoom(dir);
    QVERIFY(!scene.isEmpty());
    const Run r = runLucerna(QStringList{"grid", scene, "--task-area", "desk"} + kFast);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
    const QString& out = r.out;
    QVERIFY2(out.contains("grid 'desk': 2 x 2 points"), qPrintable(out));
    // The figures: Ez over the area at 1.2 m above the lowest point (the room is the scene's
    // bounds), the modelling ratio Ez / Eh, the walls and the ceiling.
    const QRegularExpressionMatch eh = QRegularExpression("\nEavg ([0-9.]+) lx").match(out);
    const QRegularExpressionMatch ez = QRegularExpression(
        "\nEz at 1.20 m above the floor \\(seated, floor of the scene's bounds\\): Eavg ([0-9.]+) lx \\+- ([0-9.]+) lx, "
        "Emin [0-9.]+ lx, U0 [0-9.]+ \\+- [0-9.]+ \\(4 points\\)\n").match(out);
    const QRegularExpressionMatch modelling = QRegularExpression("\nmodelling Ez/Eh ([0-9.]+) \\(guidance 0.30 to 0.60: ").match(out);
    const QRegularExpressionMatch walls =
        QRegularExpression("\nwalls of the scene's bounds: Eavg ([0-9.]+) lx \\+- ([0-9.]+) lx, .* \\(([0-9]+) points\\)\n").match(out);
    const QRegularExpressionMatch ceiling =
        QRegularExpression("\nceiling of the scene's bounds: Eavg ([0-9.]+) lx \\+- ([0-9.]+) lx, .* \\(([0-9]+) points\\)\n").match(out);
    QVERIFY2(eh.hasMatch() && ez.hasMatch() && modelling.hasMatch() && walls.hasMatch() && ceiling.hasMatch(), qPrintable(out));
    QVERIFY(std::abs(decimal(modelling.captured(1)) - decimal(ez.captured(1)) / decimal(eh.captured(1))) <= 0.006);
    // EN 12464-1's spacing on a 3 m wall: 7 x 7 points; four walls.
    QCOMPARE(walls.captured(3).toInt(), 4 * 49);
    QCOMPARE(ceiling.captured(3).toInt(), 49);
    QVERIFY2(out.contains("\nEz grid: 2 x 2 points, error bar (95%) at most "), qPrintable(out));
    QVERIFY2(out.contains("\nroom surface grids: 5 grids, 245 points, error bar (95%) at most "), qPrintable(out));

    // One list of checks: Em, U0, UGR, Ra, then Ez and the surfaces (maintained values: judged),
    // each against the figure printed above.
    const qsizetype em = out.indexOf("\n  Em "), ra = out.indexOf("\n  Ra not stated"), ezCheck = out.indexOf("\n  Ez ");
    QVERIFY2(em > 0 && ra > em && ezCheck > ra, qPrintable(out));
    const auto check = [&](const QString& quantity, const QString& required, const QRegularExpressionMatch& figure) {
        const QRegularExpressionMatch m = QRegularExpression("\n  " + quantity + " ([0-9]+) lx \\+- ([0-9.]+) lx >= " + required +
                                                             " lx: (met|borderline|not met) \\(margin ")
                                              .match(out);
        QVERIFY2(m.hasMatch(), qPrintable(quantity + " in\n" + out));
        QVERIFY2(std::abs(decimal(m.captured(1)) - decimal(figure.captured(1))) <= 0.55, qPrintable(out));
        QVERIFY(m.capturedStart() > ra);
    };
    check("Ez", "150", ez);
    check("Ewall", "150", walls);
    check("Eceiling", "100", ceiling);
    for (const char* u0 : {"\n  U0,z ", "\n  U0,wall ", "\n  U0,ceiling "})
        QVERIFY2(out.indexOf(u0) > ra, qPrintable(QString(u0) + " in\n" + out));
    QVERIFY(!out.contains("not computed (>= 150 lx required)"));

    // The surrounding zone: its figures, its requirement from the task's Em, its checks.
    QVERIFY2(QRegularExpression("\nsurrounding zone \\(0.5 m, [0-9]+ points\\): Eavg [0-9.]+ lx").match(out).hasMatch(),
             qPrintable(out));
    QVERIFY2(out.contains("\n  required (EN 12464-1, task Em 500 lx): Em 300 lx, U0 0.40\n"), qPrintable(out));
    QVERIFY2(QRegularExpression("\n  Em [0-9]+ lx \\+- [0-9.]+ lx >= 300 lx: (met|borderline|not met)").match(out).hasMatch(),
             qPrintable(out));
    // The table is the desk's own 2 x 2 points, not the zone's.
    QVERIFY2(QRegularExpression("\n( +[0-9]+\\.[0-9]){2}\n( +[0-9]+\\.[0-9]){2}\n$").match(out).hasMatch(), qPrintable(out));
}

void TestGridTaskArea::horizontalOnlyComputesNone() {
    QTemporaryDir dir;
    const QString scene = writeRoom(dir);
    const Run r = runLucerna(QStringList{"grid", scene, "--task-area", "desk", "--horizontal-only"} + kFast);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
    for (const char* absent : {"Ez at", "modelling", "walls of", "ceiling of", "Ez grid", "room surface grids"})
        QVERIFY2(!r.out.contains(absent), qPrintable(QString(absent) + " in\n" + r.out));
    for (const char* line : {"\n  Ez not computed (>= 150 lx required)", "\n  Ewall not computed (>= 150 lx required)",
                             "\n  Eceiling not computed (>= 100 lx required)", "\n  Em "})
        QVERIFY2(r.out.contains(line), qPrintable(QString(line) + " not in\n" + r.out));
    QVERIFY(r.out.contains("surrounding zone (0.5 m, "));  // the zones are the horizontal grid's
}

void TestGridTaskArea::cylindricalForAnAreaWithoutActivity() {
    QTemporaryDir dir;
    const QString scene = writeRoom(dir);
    const Run r = runLucerna(QStringList{"grid", scene, "--task-area", "counter", "--cylindrical"} + kFast);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
    QVERIFY2(r.out.contains("\nEz at 1.60 m above the floor (standing, floor of the scene's bounds): Eavg "), qPrintable(r.out));
    QVERIFY2(r.out.contains("\ntask area 'counter' names no activity: nothing to check\n"), qPrintable(r.out));
    QVERIFY(!r.out.contains("walls of") && !r.out.contains("\n  Ez "));
    const Run surfaces = runLucerna(QStringList{"grid", scene, "--task-area", "counter", "--room-surfaces"} + kFast);
    QVERIFY2(surfaces.exitCode == 0, qPrintable(surfaces.err + surfaces.out));
    QVERIFY2(surfaces.out.contains("\nwalls of the scene's bounds: Eavg ") && surfaces.out.contains("\nceiling of the scene's bounds: Eavg "),
             qPrintable(surfaces.out));
    QVERIFY(!surfaces.out.contains("Ez at"));
}

void TestGridTaskArea::cylindricalGridWithoutTaskArea() {
    QTemporaryDir dir;
    const QString scene = writeRoom(dir);
    const QStringList plane = {"grid", scene, "--corner", "1,1.2,2", "--u", "1,0,0", "--v", "0,0,-1", "--spacing", "0.5"};
    const Run ez = runLucerna(plane + QStringList{"--cylindrical"} + kFast);
    QVERIFY2(ez.exitCode == 0, qPrintable(ez.err + ez.out));
    QVERIFY2(ez.out.contains("2 x 2 points, spacing 0.5 x 0.5 m, method path; cylindrical illuminance Ez about the grid's normal\n"),
             qPrintable(ez.out));
    const QRegularExpressionMatch m = QRegularExpression("\nEz: Eavg ([0-9.]+) lx").match(ez.out);
    QVERIFY2(m.hasMatch(), qPrintable(ez.out));
    // The desk's Ez grid is this one (1.2 m above the floor, the desk's rectangle and spacing):
    // the same seed gives the same figure.
    const Run desk = runLucerna(QStringList{"grid", scene, "--task-area", "desk", "--cylindrical"} + kFast);
    QVERIFY2(desk.out.contains("Ez at 1.20 m above the floor (seated, floor of the scene's bounds): Eavg " + m.captured(1) + " lx"),
             qPrintable(m.captured(1) + " not in\n" + desk.out));
    const Run planar = runLucerna(plane + kFast);
    QVERIFY(planar.exitCode == 0 && !planar.out.contains("cylindrical") && planar.out.contains("\nEavg "));
}

void TestGridTaskArea::refusesBadCombinations() {
    QTemporaryDir dir;
    const QString scene = writeRoom(dir);
    const struct {
        QStringList args;
        const char* message;
    } rows[] = {
        {{"--work-plane", "0.8", "--room-surfaces"}, "--room-surfaces: only with --task-area NAME"},
        {{"--work-plane", "0.8", "--horizontal-only"}, "--horizontal-only: only with --task-area NAME"},
        {{"--task-area", "desk", "--horizontal-only", "--cylindrical"}, "--horizontal-only: not with --cylindrical or --room-surfaces"},
        {{"--work-plane", "0.8", "--cylindrical", "--daylight-factor"}, "--cylindrical: not with --daylight-factor"},
    };
    for (const auto& row : rows) {
        const Run r = runLucerna(QStringList{"grid", scene} + row.args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(row.message) && r.err.count('\n') == 1, qPrintable(r.err));
    }
}

QTEST_GUILESS_MAIN(TestGridTaskArea)
#include "test_grid_task_area.moc"
