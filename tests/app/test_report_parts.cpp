// The report's parts as data, before any PDF (report/): the luminaire data sheets of the office
// floor (their figures as the files state them, the UGR tables), the polar diagram both the light
// panel and the report draw, the room summary of a constructed room, and the render's stop at its
// error target. The whole report, the command and the window: test_report.

#include "process_run.h"
#include "core/photometry/luminaire.h"
#include "core/scene/scene_io.h"
#include "render/display/polar_diagram.h"
#include "report/luminaire_data_sheet.h"
#include "report/luminaire_schedule.h"
#include "report/report_builder.h"
#include "report/room_summary.h"
#include "report_test_helpers.h"

#include <QPainter>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace lucerna;
using namespace lucerna::test;

class TestReportParts : public QObject {
    Q_OBJECT

private slots:
    void dataSheetsOfTheOfficeFloor();
    void polarDiagramOfAnIsotropicSource();
    void roomSummaryOfAConstructedRoom();
    void renderStopsAtItsErrorTarget();
};

// The data sheets' intermediate data on the office floor: one per type, with the counts, the
// figures its file states and its UGR tables at the flux as installed; the point-light version
// has none, and its schedule page says why.
void TestReportParts::dataSheetsOfTheOfficeFloor() {
    const Scene scene = loadScene((kScenes + "office_floor.json").toStdString());
    const std::vector<LuminaireDataSheet> sheets = luminaireDataSheets(scene, luminaireSchedule(scene));
    QCOMPARE(int(sheets.size()), 2);
    for (size_t i = 0; i < 2; ++i) {
        const LuminaireDataSheet& s = sheets[i];
        const OfficeType& type = kOfficeTypes[i];
        const GoniometricDistribution d = loadLuminaireFile((kScenes + type.file).toStdString());
        QCOMPARE(QString::fromStdString(s.file), type.file);
        QCOMPARE(s.count, type.count);
        QVERIFY(std::abs(s.lumensEach - type.lumens) < 0.05);
        QCOMPARE(s.product, d.name);
        QCOMPARE(s.watts, d.inputWatts);
        QVERIFY(std::abs(*s.efficacy() - d.integratedFlux() / *d.inputWatts) < 1e-9);
        QCOMPARE(s.colourRenderingIndex, d.colourRenderingIndex);
        QCOMPARE(s.temperatureK, d.colourTemperatureK);
        QCOMPARE(s.sceneTemperatureK, std::optional<double>(4000.0));
        QVERIFY(std::abs(d.maxIntensity() * s.cdPerKlmPerTableCd() - d.maxIntensity() * 1000 / d.integratedFlux()) < 1e-9);
        QCOMPARE(int(s.ugr.size()), 2);
        UgrLuminaire luminaire;
        luminaire.distribution = &d;
        luminaire.fluxLm = type.lumens;
        for (size_t k = 0; k < 2; ++k) {
            const UgrTable expected = ugrTable(luminaire, k == 0 ? 1.0 : 0.25);
            QCOMPARE(s.ugr[k].spacingToHeight, expected.spacingToHeight);
            QCOMPARE(s.ugr[k].values.size(), expected.values.size());
            for (size_t r = 0; r < expected.values.size(); ++r)
                for (int v = 0; v < 2; ++v)
                    for (size_t c = 0; c < 5; ++c)
                        QVERIFY(std::abs(s.ugr[k].values[r][size_t(v)][c] - expected.values[r][size_t(v)][c]) < 1e-9);
        }
    }
    // What the files state: the IES file power, no CCT, no Ra; the EULUMDAT file all three.
    QVERIFY(sheets[0].watts && !sheets[0].temperatureK && !sheets[0].colourRenderingIndex);
    QCOMPARE(sheets[1].temperatureK, std::optional<double>(4000.0));
    QCOMPARE(sheets[1].colourRenderingIndex, std::optional<double>(80.0));

    REQUIRE_POPPLER();
    const Scene points = loadScene((kScenes + "office_floor_points.json").toStdString());
    QVERIFY(luminaireDataSheets(points, luminaireSchedule(points)).empty());
    QTemporaryDir dir;
    const QString pdf = dir.filePath("points.pdf");
    const Run r = runLucerna(QStringList{"report", kScenes + "office_floor_points.json", "-o", pdf, "--spp", "2"} + kSmall);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QString text = pdfText(pdf);
    QVERIFY(!text.contains("Luminaire data sheet"));
    QCOMPARE(text.count("Point and spot lights and emitting objects have no photometric file: no data sheet."), 1);
}

// The polar diagram both the light panel and the report draw: an isotropic source of 100 cd,
// 79.6 cd/klm, is a circle of that radius on rings of 20 cd/klm up to 80, both as the path and
// as painted.
void TestReportParts::polarDiagramOfAnIsotropicSource() {
    GoniometricDistribution d;
    d.cAngles = {0, 90, 180, 270, 360};
    d.gammaAngles = {0, 45, 90, 135, 180};
    d.candela.assign(d.cAngles.size() * d.gammaAngles.size(), 100.0);
    const double flux = d.integratedFlux();
    QVERIFY(std::abs(flux - 400 * std::numbers::pi) < 1e-9 * flux);
    const double perKlm = 1000 / flux, value = 100 * perKlm;
    const PolarRings rings = polarRings(value);
    QCOMPARE(rings.step, 20.0);
    QCOMPARE(rings.outer, 80.0);
    const QPointF centre(300, 300);
    for (double c : {0.0, 90.0}) {
        const QPainterPath path = polarCurve(d, c, c + 180, perKlm, centre, 250, rings.outer);
        QCOMPARE(path.elementCount(), 361);
        for (int i = 0; i < path.elementCount(); ++i) {
            const QPainterPath::Element e = path.elementAt(i);
            QVERIFY(std::abs(std::hypot(e.x - centre.x(), e.y - centre.y()) - 250 * value / 80) < 1e-9);
        }
    }

    QImage image(600, 560, QImage::Format_RGB32);
    image.fill(Qt::white);
    PolarDiagramStyle style;
    style.font = QFont("DejaVu Sans", 8);
    style.curvePen = 3;
    style.c90Colour = style.c0Colour;  // both planes blue: every pixel of the curve counts
    PolarFrame frame;
    {
        QPainter p(&image);
        p.setRenderHint(QPainter::Antialiasing);
        frame = polarFrame(QRectF(image.rect()), style.font, p);
        paintPolarDiagram(p, QRectF(image.rect()), d, perKlm, style);
    }
    QVERIFY(frame.radius > 200);
    QCOMPARE(frame.centre, QPointF(300, 280));
    const double expected = frame.radius * value / rings.outer;
    int quadrants[4] = {0, 0, 0, 0};
    double worst = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (!(c.blue() > c.red() + 80 && c.blue() > c.green() + 40)) continue;
            const double dx = x + 0.5 - frame.centre.x(), dy = y + 0.5 - frame.centre.y(), r = std::hypot(dx, dy);
            if (r > frame.radius + 4) continue;  // the legend's sample, in the corner
            worst = std::max(worst, std::abs(r - expected));
            ++quadrants[(dx > 0 ? 1 : 0) + (dy > 0 ? 2 : 0)];
        }
    QVERIFY2(worst <= style.curvePen / 2 + 1.5, qPrintable(QString("a curve pixel %1 px off the circle").arg(worst)));
    for (int q : quadrants) QVERIFY2(q > 200, qPrintable(QString("%1 pixels in a quadrant").arg(q)));
    QVERIFY(image.save("polar_diagram_isotropic.png"));
}

namespace {

// A room of 5 x 4 x 2.8 m: a reddish floor, grey walls, a bluish ceiling; a desk top (up, a
// larger reflectance, less area than the floor), a screen of two faces (sideways, dark) and a
// window pane (glazing: no diffuse part, not counted); one panel and one point light; CIE 97's
// factors.
QString writeRoomScene(const QTemporaryDir& dir) {
    const QString ies = QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaires/office_panel.ies");
    const QString scene = QStringLiteral(R"({
  "lucerna": 1, "meters_per_unit": 1,
  "camera": {"position": [0.3, 1.6, 0.3], "target": [4, 0.8, 3.5], "up": [0, 1, 0], "fov_y": 60, "resolution": [32, 24]},
  "materials": {"floor": {"type": "diffuse", "albedo": [0.5, 0.2, 0.1]}, "wall": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]},
                "ceiling": {"type": "diffuse", "albedo": [0.7, 0.8, 0.9]}, "desk": {"type": "diffuse", "albedo": [0.9, 0.9, 0.9]},
                "screen": {"type": "diffuse", "albedo": [0.1, 0.1, 0.1]}, "pane": {"type": "glazing", "transmittance": [0.7, 0.7, 0.7]}},
  "objects": [
    {"name": "floor", "material": "floor", "mesh": {"quad": [[0, 0, 0], [0, 0, 4], [5, 0, 4], [5, 0, 0]]}},
    {"name": "ceiling", "material": "ceiling", "mesh": {"quad": [[0, 2.8, 0], [5, 2.8, 0], [5, 2.8, 4], [0, 2.8, 4]]}},
    {"name": "north", "material": "wall", "mesh": {"quad": [[0, 0, 0], [5, 0, 0], [5, 2.8, 0], [0, 2.8, 0]]}},
    {"name": "south", "material": "wall", "mesh": {"quad": [[0, 0, 4], [0, 2.8, 4], [5, 2.8, 4], [5, 0, 4]]}},
    {"name": "west", "material": "wall", "mesh": {"quad": [[0, 0, 0], [0, 2.8, 0], [0, 2.8, 4], [0, 0, 4]]}},
    {"name": "east", "material": "wall", "mesh": {"quad": [[5, 0, 0], [5, 0, 4], [5, 2.8, 4], [5, 2.8, 0]]}},
    {"name": "desk", "material": "desk", "mesh": {"quad": [[1, 0.75, 1], [1, 0.75, 1.8], [2.6, 0.75, 1.8], [2.6, 0.75, 1]]}},
    {"name": "screen front", "material": "screen", "mesh": {"quad": [[1, 0.75, 1.8], [2.6, 0.75, 1.8], [2.6, 1.95, 1.8], [1, 1.95, 1.8]]}},
    {"name": "screen back", "material": "screen", "mesh": {"quad": [[1, 0.75, 1.81], [1, 1.95, 1.81], [2.6, 1.95, 1.81], [2.6, 0.75, 1.81]]}},
    {"name": "window", "material": "pane", "mesh": {"quad": [[4.99, 0.9, 1], [4.99, 0.9, 3], [4.99, 2.4, 3], [4.99, 2.4, 1]]}}
  ],
  "lights": [{"name": "panel", "type": "luminaire", "file": "%1", "position": [2.5, 2.79, 2], "direction": [0, -1, 0], "lumens": 3600},
             {"name": "desk lamp", "type": "point", "position": [1.5, 1.2, 1.2], "lumens": 400}],
  "maintenance_factor": {"llmf": 0.9, "lmf": 0.95}
})")
                              .arg(ies);
    const QString path = dir.filePath("room.json");
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(scene.toUtf8());
    return path;
}

}  // namespace

// The room summary: the extent, each main surface's material by area among the faces facing
// its way (glazing left out) with its luminance-weighted albedo, the maintenance factor and the
// load of the lights that state it.
void TestReportParts::roomSummaryOfAConstructedRoom() {
    QTemporaryDir dir;
    const Scene scene = loadScene(writeRoomScene(dir).toStdString());
    const Schedule schedule = luminaireSchedule(scene);
    const RoomSummary r = roomSummary(scene, schedule);
    const auto near = [](double a, double b) { return std::abs(a - b) < 1e-9; };
    QVERIFY(near(r.widthM, 5) && near(r.depthM, 4) && near(r.heightM, 2.8));
    const MainSurface& floor = r.surfaces[0];
    QCOMPARE(floor.role, std::string("Floor"));
    QCOMPARE(floor.material, std::string("floor"));
    QVERIFY(near(floor.reflectance, 0.2126 * 0.5 + 0.7152 * 0.2 + 0.0722 * 0.1));
    QVERIFY(near(floor.areaM2, 20) && near(floor.facingAreaM2, 20 + 1.6 * 0.8));
    const MainSurface& walls = r.surfaces[1];
    QCOMPARE(walls.material, std::string("wall"));
    QVERIFY(near(walls.reflectance, 0.6));
    QVERIFY(near(walls.areaM2, 2 * (5 + 4) * 2.8) && near(walls.facingAreaM2, 2 * (5 + 4) * 2.8 + 2 * 1.6 * 1.2));
    const MainSurface& ceiling = r.surfaces[2];
    QCOMPARE(ceiling.material, std::string("ceiling"));
    QVERIFY(near(ceiling.reflectance, 0.2126 * 0.7 + 0.7152 * 0.8 + 0.0722 * 0.9));
    QVERIFY(near(ceiling.areaM2, 20) && near(ceiling.facingAreaM2, 20));
    QVERIFY(near(r.maintenance.lowest, 0.9 * 0.95) && near(r.maintenance.highest, 0.9 * 0.95));
    QVERIFY(r.sceneMaintenance && r.sceneMaintenance->lampLumenMaintenance == 0.9);
    QCOMPARE(r.luminaires, 2);
    QCOMPARE(r.withoutWatts, 1);  // the point light states no power
    QCOMPARE(r.connectedLoadW, std::optional<double>(30.0));
    QVERIFY(near(r.floorAreaM2, 20));
}

// The render stops at the first check (every 8 passes from 16) where its estimated relMSE is
// within the target, well before its maximum; without a target it runs every pass.
void TestReportParts::renderStopsAtItsErrorTarget() {
    QTemporaryDir dir;
    const SceneSnapshot scene = std::make_shared<const Scene>(loadScene(writeRoomScene(dir).toStdString()));
    ReportSettings s = smallSettings();
    s.glare = false;
    s.renderSpp = 16;
    s.renderRelmse = 0;
    CancellationToken token;
    TaskContext ctx(token);
    const ReportData all = buildReport(scene, "room.json", s, ctx);
    QVERIFY(all.renders);
    QCOMPARE(all.renders->passes, 16);
    const double at16 = all.renders->estimatedRelmse;
    QVERIFY(at16 > 0);
    // A third of the error at 16 passes takes about 48: stopped at a check, below the maximum.
    s.renderSpp = 256;
    s.renderRelmse = at16 / 3;
    const ReportData stopped = buildReport(scene, "room.json", s, ctx);
    QVERIFY(stopped.renders);
    const int passes = stopped.renders->passes;
    QVERIFY2(passes >= 24 && passes <= 128 && passes % 8 == 0, qPrintable(QString::number(passes)));
    QVERIFY(stopped.renders->estimatedRelmse <= s.renderRelmse);
}

QTEST_MAIN(TestReportParts)
#include "test_report_parts.moc"
