// The report's EN 12464-1:2021 figures (report/area_extras.h; README, "Reports"): in a small box
// room lit by two panels with a maintenance factor, a desk area of 5.26.2 (2021: Ez 150 lx,
// walls 150 lx, ceiling 100 lx, each U0 0.10) and a second area in the same room: Ez over each
// area at the seated height, the room's walls and ceiling computed once for both, the zones
// around the desk, all checked in the area's one list and printed on its page and the method
// page; and a scene with a drawn room (the `rooms` key) summarised room by room with its
// reflectances, openings and its walls' and ceiling's illuminance.

#include "process_run.h"
#include "core/scene/room_geometry.h"
#include "core/scene/scene_io.h"
#include "report/plan_figure.h"
#include "report/report_builder.h"
#include "report/report_text.h"
#include "report/report_writer.h"

#include <QFile>
#include <QImage>
#include <QPainter>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <set>
#include <thread>

using namespace lucerna;
using namespace lucerna::test;

namespace {

const QString kPanel = QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaires/office_panel.ies");

QString writeFile(const QTemporaryDir& dir, const QString& name, const QString& text) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(text.toUtf8());
    return path;
}

// A 4 x 3 x 3 m box (objects, no `rooms`), two panels, maintenance factor 0.8; a desk area
// with a surrounding zone of 0.5 m and a background area of 3 m, a reading area by the wall, and
// a filing area (5.26.1, which the 2021 table here lacks: checked against 2011, no extras).
QString writeBoxRoom(const QTemporaryDir& dir) {
    return writeFile(dir, "box.json", QStringLiteral(R"({
  "lucerna": 1, "meters_per_unit": 1,
  "camera": {"position": [0.3, 1.6, 0.3], "target": [3, 0.8, 2.5], "up": [0, 1, 0], "fov_y": 60, "resolution": [32, 24]},
  "materials": {"floor": {"type": "diffuse", "albedo": [0.2, 0.2, 0.2]}, "wall": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
                "ceiling": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]}},
  "objects": [
    {"name": "floor", "material": "floor", "mesh": {"quad": [[0, 0, 0], [0, 0, 3], [4, 0, 3], [4, 0, 0]]}},
    {"name": "ceiling", "material": "ceiling", "mesh": {"quad": [[0, 3, 0], [4, 3, 0], [4, 3, 3], [0, 3, 3]]}},
    {"name": "north", "material": "wall", "mesh": {"quad": [[0, 0, 0], [4, 0, 0], [4, 3, 0], [0, 3, 0]]}},
    {"name": "south", "material": "wall", "mesh": {"quad": [[0, 0, 3], [0, 3, 3], [4, 3, 3], [4, 0, 3]]}},
    {"name": "west", "material": "wall", "mesh": {"quad": [[0, 0, 0], [0, 3, 0], [0, 3, 3], [0, 0, 3]]}},
    {"name": "east", "material": "wall", "mesh": {"quad": [[4, 0, 0], [4, 0, 3], [4, 3, 3], [4, 3, 0]]}}
  ],
  "lights": [{"name": "p1", "type": "luminaire", "file": "%1", "position": [1.3, 2.99, 1.5], "direction": [0, -1, 0], "lumens": 3600},
             {"name": "p2", "type": "luminaire", "file": "%1", "position": [2.7, 2.99, 1.5], "direction": [0, -1, 0], "lumens": 3600}],
  "maintenance_factor": 0.8,
  "task_areas": [
    {"name": "Desk", "corner": [1.2, 0.75, 1], "u": [0, 0, 1], "v": [1.6, 0, 0], "activity": "5.26.2",
     "surrounding_m": 0.5, "background_m": 3},
    {"name": "Reading", "corner": [0.3, 0.75, 0.3], "u": [0, 0, 0.6], "v": [0.6, 0, 0], "activity": "5.26.2"},
    {"name": "Filing", "corner": [3.2, 0.75, 2.2], "u": [0, 0, 0.5], "v": [0.5, 0, 0], "activity": "5.26.1"}
  ]
})").arg(kPanel));
}

ReportSettings quickSettings() {
    ReportSettings s;
    s.grid.targetRelativeError = 0.15;
    s.grid.seed = 7;
    s.grid.samplesPerPass = 8;
    s.glare = false;
    s.renders = false;
    return s;
}

ReportData build(const SceneSnapshot& scene, const ReportSettings& settings) {
    CancellationToken token;
    TaskContext ctx(token);
    return buildReport(scene, "scene.json", settings, ctx);
}

std::vector<std::string> quantities(const std::vector<RequirementCheck>& checks) {
    std::vector<std::string> q;
    for (const RequirementCheck& c : checks) q.push_back(c.quantity);
    return q;
}

const RequirementCheck* findCheck(const std::vector<RequirementCheck>& checks, const std::string& quantity) {
    const auto it = std::find_if(checks.begin(), checks.end(), [&](const RequirementCheck& c) { return c.quantity == quantity; });
    return it == checks.end() ? nullptr : &*it;
}

QString pdfText(const ReportData& data, const QTemporaryDir& dir) {
    const QString pdf = dir.filePath("report.pdf");
    if (writeReportPdf(data, pdf.toStdString()) < 1) return {};
    // Laid out as on the page, every run of white space one space: a phrase wrapped between
    // lines reads whole.
    return runProgram("pdftotext", {"-layout", pdf, "-"}).out.simplified();
}

}  // namespace

class TestReport2021 : public QObject {
    Q_OBJECT
private slots:
    void boxRoomCarriesThe2021Figures();
    void roomsSceneIsSummarisedRoomByRoom();
    void extrasAreAStageThatCancels();
    void valuesContinueUnderTheirHeading();
};

void TestReport2021::boxRoomCarriesThe2021Figures() {
    QTemporaryDir dir;
    const SceneSnapshot scene = std::make_shared<const Scene>(loadScene(writeBoxRoom(dir).toStdString()));
    const ReportData data = build(scene, quickSettings());
    QCOMPARE(data.areas.size(), size_t(3));
    const AreaReport& desk = data.areas[0];
    QVERIFY(desk.requirement && desk.requirement->edition == StandardEdition::En12464_2021);

    // Ez at 1.2 m above the floor (seated), over the area's own points.
    QVERIFY(desk.cylindrical);
    QCOMPARE(desk.cylindrical->heightAboveFloorM, kSeatedCylindricalHeightM);
    QVERIFY(std::abs(desk.cylindrical->grid.corner.y - 1.2) < 1e-12);
    QCOMPARE(desk.cylindrical->layout.points.size(), desk.layout.points.size());
    QVERIFY(desk.cylindrical->figures.grid.average > 0 && desk.cylindrical->figures.errors);

    // The walls and ceiling of the one room box (the scene's bounds), computed once for both areas.
    QCOMPARE(data.roomSurfaces.size(), size_t(1));
    const RoomSurfacesReport& room = data.roomSurfaces[0];
    QVERIFY(room.result.complete);
    QCOMPARE(room.result.grids.size(), size_t(5));
    QCOMPARE(room.areas, (std::vector<std::string>{"Desk", "Reading"}));
    QCOMPARE(desk.roomSurfaces, std::optional<size_t>(0));
    QCOMPARE(data.areas[1].roomSurfaces, std::optional<size_t>(0));
    QCOMPARE(room.settings.targetRelativeError, 0.15 * quickSettings().roomSurfaceErrorFactor);
    QVERIFY(room.result.walls.points > 0 && room.result.ceiling.points > 0);

    // One list of checks: 2011's four, then the 2021 figures, each on what was computed, and
    // checked as maintained values (a maintenance factor applies).
    QCOMPARE(quantities(desk.checks), (std::vector<std::string>{"Em", "U0", "UGR", "Ra", "Ez", "U0,z", "Ewall", "U0,wall",
                                                                "Eceiling", "U0,ceiling"}));
    const RequirementCheck* ez = findCheck(desk.checks, "Ez");
    QVERIFY(ez && ez->achieved && *ez->achieved == desk.cylindrical->figures.grid.average);
    QCOMPARE(ez->required, 150.0);
    QVERIFY(ez->outcome != CheckOutcome::NotChecked && ez->error > 0);
    const RequirementCheck* wall = findCheck(desk.checks, "Ewall");
    QVERIFY(wall && wall->achieved && *wall->achieved == room.result.walls.stats.average);
    const RequirementCheck* ceiling = findCheck(desk.checks, "Eceiling");
    QVERIFY(ceiling && ceiling->achieved && *ceiling->achieved == room.result.ceiling.stats.average);
    QCOMPARE(ceiling->required, 100.0);
    // Both areas check the same walls.
    QCOMPARE(*findCheck(data.areas[1].checks, "Ewall")->achieved, *wall->achieved);
    // Two panels of 3600 lm (x 0.8) in 12 m²: the walls and ceiling, lit directly and by the
    // floor and walls, are well inside the range of the area's own illuminance.
    QVERIFY2(room.result.walls.stats.average > 20 && room.result.walls.stats.average < desk.statistics.average,
             qPrintable(QString::number(room.result.walls.stats.average)));
    QVERIFY(room.result.ceiling.stats.average > 5 && room.result.ceiling.stats.average < desk.statistics.average);

    // The modelling ratio, guidance only: Ez over the area's Eavg, and no check of it.
    QVERIFY(desk.modellingRatio);
    QCOMPARE(*desk.modellingRatio, desk.cylindrical->figures.grid.average / desk.statistics.average);

    // The zones around the desk, clipped to the room, with their requirements (500 lx -> 300 lx, 100 lx).
    QCOMPARE(desk.zones.size(), size_t(2));
    QCOMPARE(desk.zones[0].name, std::string("surrounding zone"));
    QVERIFY(desk.zones[0].requirement && desk.zones[0].requirement->maintainedLux == 300);
    QVERIFY(desk.zones[1].requirement && desk.zones[1].requirement->maintainedLux == 100);
    QCOMPARE(desk.zones[0].result.lux.size(), desk.zones[0].grid.points.size());
    QCOMPARE(quantities(desk.zones[0].checks), (std::vector<std::string>{"Em", "U0"}));
    QVERIFY(data.areas[1].zones.empty());

    // The filing area's activity falls back to 2011: its four checks, nothing computed beyond its grid.
    const AreaReport& filing = data.areas[2];
    QVERIFY(filing.requirement && filing.requirement->edition == StandardEdition::En12464_2011);
    QCOMPARE(quantities(filing.checks), (std::vector<std::string>{"Em", "U0", "UGR", "Ra"}));
    QVERIFY(!filing.cylindrical && !filing.roomSurfaces && !filing.modellingRatio);

    // The pages: the figures with their error bars, the checks, the modelling ratio as guidance,
    // the edition and how the figures were computed.
    QVERIFY2(!QStandardPaths::findExecutable("pdftotext").isEmpty(),
             "pdftotext (poppler-utils) is missing: packaging/install-deps.sh installs it");
    const QString text = pdfText(data, dir);
    for (const char* s : {"Cylindrical illuminance, walls, ceiling and zones", "Ez (cylindrical)", "(seated)",
                          "Ez (cylindrical, mean)", "Ewall (walls, mean)", "Eceiling (ceiling, mean)", "U0,ceiling",
                          "Surrounding zone: Em", "Background area: U0", "Checks against EN 12464-1:2021",
                          "Modelling (EN 12464-1:2021, 5.2.6; guidance", "Requirements are from EN 12464-1:2021",
                          "EN 12464-1:2021 5.26.2, Offices", "the scene's bounds: wall 1", "They are the room's, computed once for",
                          "EN 12464-1:2021 (fallback to EN 12464-1:2011 for 5.26.1"})
        QVERIFY2(text.contains(QString::fromUtf8(s)), s);
    // The desk's plan draws its zones (a band, its edge dashed; the background area's dotted)
    // and names them in its legend; the reading area has none.
    for (const char* s : {"Surrounding zone (0.5 m)", "Background area (3 m)"})
        QCOMPARE(text.count(QString::fromUtf8(s)), 1);
    {
        PlanValues values;
        values.values = desk.result.lux;
        values.insideGeometry = desk.result.insideGeometry;
        values.statistics = desk.statistics;
        const auto paint = [&](const PlanValues& v) {
            QImage image(600, 700, QImage::Format_RGB32);
            image.fill(Qt::white);
            QPainter p(&image);
            paintPlanFigure(p, QRectF(0, 0, 600, 700), *scene, desk.grid, desk.layout, v, QFont(), 3);
            return image;
        };
        const QImage without = paint(values);
        for (const ZoneReport& z : desk.zones) values.zones.push_back({qs(z.name), z.grid.strips, z.name == "background area"});
        const QImage with = paint(values);
        // The plan's pixels the zones changed: their bands and edges, tinted with the window's
        // zone colour (0, 125, 90) over the room's greys.
        int changed = 0, zoneColoured = 0;
        for (int y = 0; y < with.height() - kPlanLegendMm * 3; ++y)  // the plan, not its legend
            for (int x = 0; x < with.width(); ++x) {
                const QColor a = with.pixelColor(x, y), b = without.pixelColor(x, y);
                if (a == b) continue;
                ++changed;
                if (a.green() > a.red() + 5 && a.green() > a.blue()) ++zoneColoured;
            }
        QVERIFY2(changed > 2000 && zoneColoured > changed / 2, qPrintable(QStringLiteral("%1 %2").arg(changed).arg(zoneColoured)));
    }
    // Eavg of the walls with its error bar, as computed.
    const QString walls = QStringLiteral("%1 \u00b1 %2").arg(QString::asprintf("%.1f", room.result.walls.stats.average),
                                                             QString::asprintf("%.1f", room.result.walls.errors.average));
    QVERIFY2(text.contains(walls), qPrintable(walls));
}

// A drawn room 5 x 4 x 2.8 m with a window and a door, its surfaces generated as the window
// generates them; reflectances 20%, 50%, 70%.
void TestReport2021::roomsSceneIsSummarisedRoomByRoom() {
    QTemporaryDir dir;
    const QString path = writeFile(dir, "rooms.json", QStringLiteral(R"({
  "lucerna": 1, "meters_per_unit": 1,
  "camera": {"position": [0.5, 1.6, 0.5], "target": [4, 0.8, 3], "up": [0, 1, 0], "fov_y": 60, "resolution": [32, 24]},
  "materials": {"office floor": {"type": "diffuse", "albedo": [0.2, 0.2, 0.2]},
                "office walls": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]},
                "office ceiling": {"type": "diffuse", "albedo": [0.7, 0.7, 0.7]},
                "office glazing": {"type": "glazing", "transmittance": [0.7, 0.7, 0.7]}},
  "rooms": [{"name": "office", "outline": [[0, 0], [5, 0], [5, 4], [0, 4]], "floor_level": 0, "height": 2.8,
             "materials": {"floor": "office floor", "walls": "office walls", "ceiling": "office ceiling"},
             "openings": [{"type": "window", "wall": 1, "offset": 1.5, "sill": 0.9, "width": 2, "height": 1.4, "glazing": "office glazing"},
                          {"type": "door", "wall": 3, "offset": 0.5, "width": 0.9, "height": 2.1}]}],
  "objects": [],
  "lights": [{"name": "p1", "type": "luminaire", "file": "%1", "position": [2.5, 2.79, 2], "direction": [0, -1, 0], "lumens": 3600,
              "maintenance_factor": 0.75}],
  "maintenance_factor": 0.8,
  "task_areas": [{"name": "Desk", "corner": [1.5, 0.75, 1.2], "u": [0, 0, 1.6], "v": [2, 0, 0], "activity": "5.26.2"}]
})").arg(kPanel));
    Scene loaded = loadScene(path.toStdString());
    std::set<std::string> taken;
    for (const Light& l : loaded.lights) taken.insert(l.name);
    const std::vector<Object> surfaces = roomSurfaces(loaded.rooms[0], loaded, taken);
    loaded.objects.insert(loaded.objects.end(), surfaces.begin(), surfaces.end());
    const SceneSnapshot scene = std::make_shared<const Scene>(std::move(loaded));
    const ReportData data = build(scene, quickSettings());

    QVERIFY(!data.room);  // the one-extent summary is for scenes without rooms
    QVERIFY(data.rooms);
    QCOMPARE(data.rooms->rooms.size(), size_t(1));
    const RoomEntry& r = data.rooms->rooms[0];
    const auto near = [](double a, double b) { return std::abs(a - b) < 1e-9; };
    QCOMPARE(r.name, std::string("office"));
    QVERIFY(r.drawn);
    QVERIFY(near(r.floorAreaM2, 20) && near(r.widthM, 5) && near(r.depthM, 4) && near(r.heightM, 2.8));
    QVERIFY(r.reflectances[0] && near(*r.reflectances[0], 0.2));
    QVERIFY(r.reflectances[1] && near(*r.reflectances[1], 0.5));
    QVERIFY(r.reflectances[2] && near(*r.reflectances[2], 0.7));
    QCOMPARE(r.materials[1], std::string("office walls"));
    QCOMPARE(r.windows, 1);
    QCOMPARE(r.doors, 1);
    QVERIFY(near(r.openingAreaM2, 2 * 1.4 + 0.9 * 2.1));
    QVERIFY(r.wallAreaM2 && near(*r.wallAreaM2, 2 * (5 + 4) * 2.8 - (2 * 1.4 + 0.9 * 2.1)));
    // The light in it has its own factor: that one applies, not the scene's.
    QCOMPARE(r.lightsInside, 1);
    QVERIFY(near(r.maintenance.lowest, 0.75) && near(r.maintenance.highest, 0.75));

    // The task area lies in the room: its box is the room's, and the room gets its walls and ceiling.
    QCOMPARE(data.areas.size(), size_t(1));
    QCOMPARE(data.areas[0].room.description, std::string("room 'office'"));
    QCOMPARE(data.roomSurfaces.size(), size_t(1));
    QVERIFY(r.walls && r.ceiling);
    QCOMPARE(r.walls->grid.average, data.roomSurfaces[0].result.walls.stats.average);
    QCOMPARE(r.ceiling->grid.average, data.roomSurfaces[0].result.ceiling.stats.average);

    QVERIFY2(!QStandardPaths::findExecutable("pdftotext").isEmpty(),
             "pdftotext (poppler-utils) is missing: packaging/install-deps.sh installs it");
    const QString text = pdfText(data, dir);
    for (const char* s : {"Room summary", "Dimensions, openings and maintenance", "1 window, 1 door", "0.75 (1 light)",
                          "room 'office': ceiling"})
        QVERIFY2(text.contains(QString::fromUtf8(s)), s);
    // A row per surface: its material, reflectance and, for walls and ceiling, Eavg with its error bar.
    const QString walls = QStringLiteral(R"(Walls\s+office walls\s+50%\s+%1 ± %2)")
                              .arg(QString::asprintf("%.1f", r.walls->grid.average), QString::asprintf("%.1f", r.walls->errors->average));
    QVERIFY2(QRegularExpression(walls).match(text).hasMatch(), qPrintable(walls));
    QVERIFY(QRegularExpression(R"(Floor\s+office floor\s+20%)").match(text).hasMatch());
    QVERIFY(QRegularExpression(R"(Ceiling\s+office ceiling\s+70%)").match(text).hasMatch());
    QVERIFY(!text.contains("Reflectances of the main surfaces"));  // the one-extent page's
}

// Ez is a stage of the report's progress: past the first area's grid the progress moves on while
// Ez converges (here toward a target it would take minutes to reach), and a cancel there ends the
// report at once, without Ez.
void TestReport2021::extrasAreAStageThatCancels() {
    QTemporaryDir dir;
    const SceneSnapshot scene = std::make_shared<const Scene>(loadScene(writeBoxRoom(dir).toStdString()));
    ReportSettings s = quickSettings();
    s.grid.targetRelativeError = 0.3;
    s.cylindricalErrorFactor = 0.002;  // Ez to 0.06%: hundreds of thousands of passes
    CancellationToken token;
    TaskContext ctx(token);
    // The shares: three grids, two Ez, one room, one pair of zones (0.5): the first grid ends at 1 / 6.5.
    const double firstGrid = 1 / 6.5;
    double seen = 0;
    std::thread watcher([&] {
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (std::chrono::steady_clock::now() < until && !token.isCancelled()) {
            seen = ctx.progress();
            if (seen > firstGrid + 0.002) token.cancel();
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        token.cancel();
    });
    const auto start = std::chrono::steady_clock::now();
    const ReportData data = buildReport(scene, "box.json", s, ctx);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    watcher.join();
    QVERIFY2(seen > firstGrid && seen < 2 * firstGrid, qPrintable(QString::number(seen)));  // within Ez's share
    QVERIFY2(seconds < 30, qPrintable(QString::number(seconds)));
    QVERIFY(!data.areas.empty() && !data.areas[0].result.lux.empty());  // the grid was done
    QVERIFY(!data.areas[0].cylindrical);                               // Ez was not
}

// A table of values longer than a page (a bench 0.45 x 2.9 m at 3 cm: 15 x 97 points, two
// blocks of columns) says on each page it continues onto whose values they are, above its
// header row repeated; so does its second block, which starts a page of its own.
void TestReport2021::valuesContinueUnderTheirHeading() {
    QTemporaryDir dir;
    QFile box(writeBoxRoom(dir));
    QVERIFY(box.open(QIODevice::ReadOnly));
    QString json = QString::fromUtf8(box.readAll());
    json.truncate(json.indexOf(QStringLiteral("\"task_areas\"")));
    json += QStringLiteral(R"("task_areas": [{"name": "Bench", "corner": [1.0, 0.75, 0.05], "u": [0.45, 0, 0],
                                              "v": [0, 0, 2.9], "spacing": 0.03}]})");
    const SceneSnapshot scene =
        std::make_shared<const Scene>(loadScene(writeFile(dir, "bench.json", json).toStdString()));
    ReportSettings s = quickSettings();
    s.grid.targetRelativeError = 0.3;  // the pages are checked, not the figures
    const ReportData data = build(scene, s);
    QCOMPARE(data.areas.size(), size_t(1));
    QCOMPARE(data.areas[0].layout.nu, 15);
    QVERIFY(data.areas[0].layout.nv > 90);
    const QString text = pdfText(data, dir);
    const QString title = QStringLiteral("Bench: illuminance at the grid points [lx]");
    QVERIFY2(text.contains(title + QStringLiteral(", columns 1 to 12 of 15 (continued) [m] x ")), qPrintable(text));
    QVERIFY2(text.contains(title + QStringLiteral(" (continued) Columns 13 to 15 of 15 [m] x ")), qPrintable(text));
    QVERIFY2(text.contains(title + QStringLiteral(", columns 13 to 15 of 15 (continued) [m] x ")), qPrintable(text));
    // Every continuation title is followed by the table's header row.
    const int continued = int(text.count(QStringLiteral(" (continued) ")));
    const int withHeader = int(text.count(QRegularExpression(R"(\(continued\) (Columns 13 to 15 of 15 )?\[m\] x [0-9.]+ x )")));
    QVERIFY2(continued >= 3 && withHeader == continued, qPrintable(QStringLiteral("%1 %2").arg(continued).arg(withHeader)));
}

QTEST_MAIN(TestReport2021)
#include "test_report_2021.moc"
