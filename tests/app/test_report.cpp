// The lighting design report (README, "Reports"; report/): `lucerna report` on the bundled office
// floor and the daylit office and on a scene with a project, task areas and activities; the PDF
// read back with poppler-utils (pdftotext, pdftoppm; packaging/install-deps.sh installs them):
// every page has content, each area's Eavg, Emin, Emax and U0 (and the daylight factor) are the
// ones `lucerna grid` prints for the same seed, samples and error target, no word lies outside
// the page's margins, the luminaire data sheets as the PDF prints them; bad input, Ctrl-C; and
// File > Export Report driven in the window. The report's parts as data (the data sheets, the
// polar diagram, the room summary, the render's stop at its error target): test_report_parts.

#include "process_run.h"
#include "core/photometry/luminaire.h"
#include "core/scene/scene_io.h"
#include "render/display/polar_diagram.h"
#include "report/luminaire_data_sheet.h"
#include "report/luminaire_schedule.h"
#include "report/report_builder.h"
#include "report/room_summary.h"
#include "ui/io/file_dialogs.h"
#include "ui/window/main_window.h"
#include "ui/calculation/report_export.h"
#include "report_test_helpers.h"
#include "window_test_helpers.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QMessageBox>
#include <QPainter>
#include <QProcess>
#include <QProgressDialog>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <charconv>
#include <cmath>
#include <csignal>
#include <numbers>

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




// "Eavg 512.3 lx, Emin 301.0 lx, Emax 702.4 lx, U0 0.588": every such line, in order.
QStringList figureLines(const QString& text) {
    static const QRegularExpression line(R"re(Eavg [0-9.]+ lx, Emin [0-9.]+ lx, Emax [0-9.]+ lx, U0 [0-9.]+)re");
    QStringList out;
    for (auto it = line.globalMatch(text); it.hasNext();) out << it.next().captured(0);
    return out;
}

QStringList dfLines(const QString& text) {
    static const QRegularExpression line(R"re(DFavg [0-9.]+%, DFmin [0-9.]+%, DFmax [0-9.]+%, uniformity DFmin/DFavg [0-9.]+)re");
    QStringList out;
    for (auto it = line.globalMatch(text); it.hasNext();) out << it.next().captured(0);
    return out;
}

// The figures `lucerna grid` prints for these arguments (its second line, or its DF line).
QString gridLine(const QStringList& args, bool daylightFactor = false) {
    const Run r = runLucerna(QStringList{"grid"} + args + kSmall);
    if (r.exitCode != 0) return "grid failed: " + r.err;
    const QStringList found = daylightFactor ? dfLines(r.out) : figureLines(r.out);
    return found.isEmpty() ? "no figures in: " + r.out : found.front();
}

// Every page rendered (pdftoppm at 30 dpi) has content between the header and the footer:
// some non-white pixels in the band where the flow writes.
void checkPagesHaveContent(const QString& pdf, int expectedPages) {
    QTemporaryDir dir;
    const Run r = runProgram("pdftoppm", {"-r", "30", "-png", pdf, dir.filePath("page")});
    QCOMPARE(r.exitCode, 0);
    const QStringList pages = QDir(dir.path()).entryList({"page*.png"}, QDir::Files, QDir::Name);
    QCOMPARE(int(pages.size()), expectedPages);
    for (const QString& name : pages) {
        const QImage page(dir.filePath(name));
        QVERIFY2(!page.isNull(), qPrintable(name));
        // Between 25 mm from the top and 25 mm from the bottom of 297 mm: no header or footer.
        const int y0 = int(page.height() * 25.0 / 297.0), y1 = int(page.height() * 272.0 / 297.0);
        int ink = 0, all = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < page.width(); ++x, ++all)
                if (qGray(page.pixel(x, y)) < 200) ++ink;
        QVERIFY2(ink > all / 200, qPrintable(QString("%1: %2 of %3 pixels inked").arg(name).arg(ink).arg(all)));
    }
}

// pdftotext -bbox: every word lies within the page less 8 mm all round (the margins are 15 to
// 20 mm; the header and footer 11 and 12 mm from the edges).
void checkWordsInsidePage(const QString& pdf) {
    const Run r = runProgram("pdftotext", {"-bbox", pdf, "-"});
    QCOMPARE(r.exitCode, 0);
    static const QRegularExpression page(R"re(<page width="([0-9.]+)" height="([0-9.]+)">)re");
    static const QRegularExpression word(
        R"re(<word xMin="([0-9.-]+)" yMin="([0-9.-]+)" xMax="([0-9.-]+)" yMax="([0-9.-]+)">([^<]*)</word>)re");
    const auto size = page.match(r.out);
    QVERIFY(size.hasMatch());
    const double width = decimal(size.captured(1)), height = decimal(size.captured(2));
    QVERIFY(std::abs(width - 595) < 2 && std::abs(height - 842) < 2);  // A4 portrait, in points
    const double margin = 8 / 25.4 * 72;
    int words = 0;
    for (auto it = word.globalMatch(r.out); it.hasNext(); ++words) {
        const auto m = it.next();
        const double x0 = decimal(m.captured(1)), y0 = decimal(m.captured(2));
        const double x1 = decimal(m.captured(3)), y1 = decimal(m.captured(4));
        QVERIFY2(x0 >= margin && y0 >= margin && x1 <= width - margin && y1 <= height - margin,
                 qPrintable(QString("'%1' at %2, %3 to %4, %5").arg(m.captured(5)).arg(x0).arg(y0).arg(x1).arg(y1)));
    }
    QVERIFY(words > 100);
}

int pageCount(const QString& pdf) {
    const Run r = runProgram("pdfinfo", {pdf});
    static const QRegularExpression pages(R"re(Pages:\s+(\d+))re");
    const auto m = pages.match(r.out);
    return m.hasMatch() ? m.captured(1).toInt() : -1;
}

// A room of 6 x 4 x 3 m under four panels, with a maintenance factor, a project and two task
// areas: desks (activity 5.26.2, the default observers) and a meeting table on a fine grid
// (activity 5.26.5, one observer), whose values fill several pages.
QString writeProjectScene(const QTemporaryDir& dir) {
    const QString ies = QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaires/office_panel.ies");
    QString lights;
    for (double x : {1.5, 4.5})
        for (double z : {1.0, 3.0})
            lights += QStringLiteral(R"({"name": "panel_%1_%2", "type": "luminaire", "file": "%3", "position": [%1, 2.99, %2],
                     "direction": [0, -1, 0], "lumens": 3600},)")
                          .arg(x)
                          .arg(z)
                          .arg(ies);
    lights.chop(1);
    const QString scene = QStringLiteral(R"({
  "lucerna": 1, "meters_per_unit": 1,
  "camera": {"position": [0.3, 1.6, 0.3], "target": [5, 0.8, 3.5], "up": [0, 1, 0], "fov_y": 60, "resolution": [96, 64]},
  "materials": {"floor": {"type": "diffuse", "albedo": [0.3, 0.3, 0.3]}, "wall": {"type": "diffuse", "albedo": [0.6, 0.6, 0.6]},
                "ceiling": {"type": "diffuse", "albedo": [0.8, 0.8, 0.8]}},
  "objects": [
    {"name": "floor", "material": "floor", "mesh": {"quad": [[0, 0, 0], [0, 0, 4], [6, 0, 4], [6, 0, 0]]}},
    {"name": "ceiling", "material": "ceiling", "mesh": {"quad": [[0, 3, 0], [6, 3, 0], [6, 3, 4], [0, 3, 4]]}},
    {"name": "north", "material": "wall", "mesh": {"quad": [[0, 0, 0], [6, 0, 0], [6, 3, 0], [0, 3, 0]]}},
    {"name": "south", "material": "wall", "mesh": {"quad": [[0, 0, 4], [0, 3, 4], [6, 3, 4], [6, 0, 4]]}},
    {"name": "west", "material": "wall", "mesh": {"quad": [[0, 0, 0], [0, 3, 0], [0, 3, 4], [0, 0, 4]]}},
    {"name": "east", "material": "wall", "mesh": {"quad": [[6, 0, 0], [6, 0, 4], [6, 3, 4], [6, 3, 0]]}}
  ],
  "lights": [%1],
  "maintenance_factor": 0.8,
  "project": {"name": "Refit of the second floor", "client": "Acme Insurance Ltd", "designer": "J. Doe, Lichtplanung",
              "notes": "Design for the refit of the open office and the meeting room. Luminaires as the schedule; ceiling height 3.00 m; reflectances ceiling 0.8, walls 0.6, floor 0.3. A long note wraps over several lines of the cover and never runs off the page, however long its words: averyveryveryveryveryveryveryveryveryveryveryveryveryveryveryveryverylongword."},
  "task_areas": [
    {"name": "Desks", "corner": [0.5, 0.75, 0.5], "u": [0, 0, 3], "v": [2.5, 0, 0], "activity": "5.26.2"},
    {"name": "Meeting table", "corner": [3.3, 0.75, 0.6], "u": [0, 0, 2.8], "v": [2.2, 0, 0], "spacing": 0.08,
     "activity": "5.26.5", "observers": [{"position": [3.2, 1.2, 2.0], "view": [1, 0, 0]}]}
  ]
})")
                              .arg(lights);
    const QString path = dir.filePath("refit.json");
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(scene.toUtf8());
    return path;
}

QString layoutText(const QString& pdf) { return runProgram("pdftotext", {"-layout", pdf, "-"}).out; }


// A UGR table's row as the data sheet prints it: "2H x 2H" and ten values, "-" where none.
QString ugrRowPattern(const UgrTable& t, size_t room) {
    QString p = QRegularExpression::escape(QStringLiteral("%1H x %2H").arg(kUgrRooms[room].x).arg(kUgrRooms[room].y));
    for (int v = 0; v < 2; ++v)
        for (double x : t.values[room][size_t(v)])
            p += QStringLiteral("\\s+") + (std::isfinite(x) ? QRegularExpression::escape(QString::number(x, 'f', 1)) : QStringLiteral("-"));
    return p + QStringLiteral("\\s*$");
}

// Each type's data sheet in the PDF's text (pdftotext -layout): its figures as the file states
// them, and both UGR tables row by row as core/photometry/ugr_table.h computes them.
void checkOfficeDataSheets(const QString& pdf) {
    const QString text = layoutText(pdf);
    for (const OfficeType& type : kOfficeTypes) {
        const GoniometricDistribution d = loadLuminaireFile((kScenes + type.file).toStdString());
        QVERIFY2(text.contains(QStringLiteral("Luminaire data sheet: ") + QString::fromStdString(d.name).left(30)), qPrintable(type.file));
        const auto line = [&](const QString& key, const QString& value) {
            const QRegularExpression re(QStringLiteral("^\\s*") + key + QStringLiteral("\\s+") + QRegularExpression::escape(value),
                                        QRegularExpression::MultilineOption);
            return re.match(text).hasMatch();
        };
        const QString watts = QString::number(*d.inputWatts, 'f', 1) + " W";
        const QString efficacy = QString::number(d.integratedFlux() / *d.inputWatts, 'f', 1) + " lm/W";
        const QString cct = d.colourTemperatureK ? QString::number(*d.colourTemperatureK, 'f', 0) + " K" : QString("-");
        const QString ra = d.colourRenderingIndex ? QString::number(*d.colourRenderingIndex, 'f', 0) : QString("-");
        QVERIFY2(line("Photometric file", type.file), qPrintable(type.file));
        QVERIFY2(line("In this scene", QString("%1 luminaire(s) of %2 lm").arg(type.count).arg(type.lumens)), qPrintable(type.file));
        QVERIFY2(line("Power", watts) && line("Efficacy", efficacy) && line("CCT", cct) && line("Ra", ra),
                 qPrintable(type.file + ": " + watts + ", " + efficacy + ", " + cct + ", " + ra));
        UgrLuminaire luminaire;
        luminaire.distribution = &d;
        luminaire.fluxLm = type.lumens;
        for (double spacing : {1.0, 0.25}) {
            const UgrTable t = ugrTable(luminaire, spacing);
            QVERIFY(text.contains(QString("UGR table, spacing-to-height S = %1H, %2 lm").arg(spacing, 0, 'f', 2).arg(type.lumens)));
            for (size_t room = 0; room < kUgrRooms.size(); ++room) {
                const QRegularExpression row(QStringLiteral("^\\s*") + ugrRowPattern(t, room), QRegularExpression::MultilineOption);
                QVERIFY2(row.match(text).hasMatch(), qPrintable(type.file + ": " + row.pattern()));
            }
        }
    }
    // The IES file states no CCT, the EULUMDAT file 4000 K; both, as the schedule, Ra.
    QVERIFY(text.contains("- (the scene renders it at 4000 K)"));
    QVERIFY(text.contains("4000 K (the scene renders it at 4000 K)"));
}

}  // namespace

class TestReport : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useTestSettings("test_report"); }
    void officeFloorReport();
    void daylitOfficeReport();
    void projectSceneReport();
    void badInputOneLine();
    void interruptedReportLeavesNoFile();
    void exportReportFromWindow();
    void exportReportCancelAndError();
};

// The bundled office floor: its two task areas (the desks and the meeting zone), each as `grid`
// computes its rectangle.
void TestReport::officeFloorReport() {
    REQUIRE_POPPLER();
    QTemporaryDir dir;
    const QString pdf = dir.filePath("office.pdf");
    const QString scene = kScenes + "office_floor.json";
    const Run r = runLucerna(QStringList{"report", scene, "-o", pdf, "--spp", "2"} + kSmall);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QString text = pdfText(pdf);
    const QStringList figures = figureLines(text);
    QCOMPARE(figures.size(), 2);
    QCOMPARE(figures[0], gridLine({scene, "--corner", "1.5,0.75,1.2", "--u", "0,0,12.2", "--v", "33,0,0", "--spacing", "1"}));
    QCOMPARE(figures[1], gridLine({scene, "--corner", "2.5,0.75,16.9", "--u", "0,0,2.2", "--v", "19,0,0", "--spacing", "0.5"}));
    QCOMPARE(figureLines(r.out), figures);  // the command prints them too
    // The method page names the command that gives an area's figures: --task-area NAME.
    QVERIFY(text.contains("--task-area \"Meeting zone\" --method path --error 0.15 --seed 7 --samples 8"));
    QCOMPARE(figures[1], gridLine({scene, "--task-area", "Meeting zone"}));
    QVERIFY(text.contains("Open-plan office floor (bundled example)"));
    QVERIFY(text.contains("Task area: Open-plan desks") && text.contains("Task area: Meeting zone"));
    // The schedule: 84 panels and 24 pendants, their power and the load per square metre.
    QVERIFY2(text.contains("Luminaire schedule") && text.contains("108") && text.contains("3288.0") &&
                 text.contains("W/m\u00b2"),
             qPrintable(text.left(3000)));
    QVERIFY(text.contains("UGR"));
    QVERIFY(text.contains("values of the new installation (no maintenance factor)"));
    checkOfficeDataSheets(pdf);
    // The room: 36 x 21.6 x 3 m, floor 0.2, walls 0.6, ceiling 0.8 (luminance-weighted).
    const QString layout = layoutText(pdf);
    QVERIFY(layout.contains("36.00 m x 21.60 m, 3.00 m high"));
    QVERIFY(QRegularExpression(R"re(Floor\s+floor\s+20%)re").match(layout).hasMatch());
    QVERIFY(QRegularExpression(R"re(Walls\s+wall\s+60%)re").match(layout).hasMatch());
    QVERIFY(QRegularExpression(R"re(Ceiling\s+ceiling\s+80%)re").match(layout).hasMatch());
    QVERIFY(layout.contains("none: maintained values not checked"));
    const int pages = pageCount(pdf);
    QVERIFY(pages >= 5);
    QVERIFY(text.contains(QString("Page %1 of %1").arg(pages)));
    checkPagesHaveContent(pdf, pages);
    checkWordsInsidePage(pdf);
}

// The daylit office: on its reference plane, the illuminance and the daylight factor as `grid`
// and `grid --daylight-factor`; the bundled interior, which names no task areas: the work plane at
// 0.8 m, as `grid --work-plane 0.8`.
void TestReport::daylitOfficeReport() {
    REQUIRE_POPPLER();
    QTemporaryDir dir;
    const QString pdf = dir.filePath("daylit.pdf");
    const QString scene = kScenes + "daylit_office.json";
    const Run r = runLucerna(QStringList{"report", scene, "-o", pdf, "--spp", "2"} + kSmall);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QString text = pdfText(pdf);
    const QStringList plane = {scene, "--corner", "0.5,0.85,0.5", "--u", "0,0,3.5", "--v", "5,0,0"};
    QCOMPARE(figureLines(text), QStringList{gridLine(plane)});
    QCOMPARE(dfLines(text), QStringList{gridLine(plane + QStringList{"--daylight-factor"}, true)});
    QVERIFY(text.contains("UGR, which rates electric lighting (CIE 117), does not apply"));
    QVERIFY(text.contains("Sun: 70000 lx direct normal"));
    QVERIFY(text.contains("CIE general sky type 12"));
    QVERIFY(text.contains("EN 17037 level"));
    const int pages = pageCount(pdf);
    checkPagesHaveContent(pdf, pages);
    checkWordsInsidePage(pdf);

    const QString interior = dir.filePath("interior.pdf");
    const Run ri = runLucerna(QStringList{"report", kScenes + "interior.json", "-o", interior, "--spp", "2"} + kSmall);
    QVERIFY2(ri.exitCode == 0, qPrintable(ri.err));
    const QString interiorText = pdfText(interior);
    QVERIFY(interiorText.contains("Task area: Work plane"));
    QCOMPARE(figureLines(interiorText), QStringList{gridLine({kScenes + "interior.json", "--work-plane", "0.8"})});
    checkPagesHaveContent(interior, pageCount(interior));
    checkWordsInsidePage(interior);
}

// A project with task areas: the cover, the checks against EN 12464-1, the maintained values,
// each area's figures as `grid` gives them for its rectangle, a table of values over pages.
void TestReport::projectSceneReport() {
    REQUIRE_POPPLER();
    QTemporaryDir dir;
    const QString scene = writeProjectScene(dir);
    const QString pdf = dir.filePath("refit.pdf");
    const Run r = runLucerna(QStringList{"report", scene, "-o", pdf, "--spp", "2"} + kSmall);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QString text = pdfText(pdf);
    for (const char* s : {"Refit of the second floor", "Acme Insurance Ltd", "J. Doe, Lichtplanung", "Task area: Desks",
                          "Task area: Meeting table", "5.26.2 Offices: Writing, typing, reading, data processing",
                          "maintained values (maintenance factor 0.80)", "Em (maintained, Eavg)", "UGR (worst observer)",
                          "Ra (lowest luminaire)", "not stated"})
        QVERIFY2(text.contains(s), s);
    const QStringList figures = figureLines(text);
    QCOMPARE(figures.size(), 2);
    QCOMPARE(figures[0], gridLine({scene, "--corner", "0.5,0.75,0.5", "--u", "0,0,3", "--v", "2.5,0,0"}));
    QCOMPARE(figures[1], gridLine({scene, "--corner", "3.3,0.75,0.6", "--u", "0,0,2.8", "--v", "2.2,0,0", "--spacing", "0.08"}));
    // The meeting table's 28 x 35 values: three blocks of columns, the header row repeated on
    // each page a block runs onto.
    QVERIFY(text.contains("Columns 25 to 28 of 28"));
    // The room summary: its extent, the three surfaces' reflectances, the maintenance factor and
    // the four panels' 30 W.
    const QString layout = layoutText(pdf);
    for (const char* s : {"6.00 m x 4.00 m, 3.00 m high", "Maintenance factor", "120.0 W, 5.00 W/m²"})
        QVERIFY2(layout.contains(QString::fromUtf8(s)), s);
    QVERIFY(QRegularExpression(R"re(Maintenance factor\s+0\.80)re").match(layout).hasMatch());
    QVERIFY(QRegularExpression(R"re(Floor\s+floor\s+30%)re").match(layout).hasMatch());
    QVERIFY(QRegularExpression(R"re(Walls\s+wall\s+60%)re").match(layout).hasMatch());
    QVERIFY(QRegularExpression(R"re(Ceiling\s+ceiling\s+80%)re").match(layout).hasMatch());
    QVERIFY(text.count("Illuminance at the grid points [lx]") == 2);
    const int pages = pageCount(pdf);
    QVERIFY2(pages >= 8, qPrintable(QString::number(pages)));
    checkPagesHaveContent(pdf, pages);
    checkWordsInsidePage(pdf);
}

void TestReport::badInputOneLine() {
    QTemporaryDir dir;
    const QString scene = kScenes + "cornell-box.json";
    const QList<QStringList> bad = {
        {"report", scene},                                             // no output
        {"report", scene, "-o", dir.filePath("r.txt")},                // not a PDF
        {"report", dir.filePath("missing.json"), "-o", dir.filePath("r.pdf")},
        {"report", scene, "-o", dir.filePath("no/such/folder/r.pdf")},
        {"report", scene, "-o", dir.filePath("r.pdf"), "--method", "magic"},
        {"report", scene, "-o", dir.filePath("r.pdf"), "--error", "0"},
        {"report", scene, "-o", dir.filePath("r.pdf"), "--bogus"},
    };
    for (const QStringList& args : bad) {
        const Run r = runLucerna(args);
        QVERIFY2(r.exitCode == 2, qPrintable(args.join(' ') + ": " + r.err));
        QVERIFY2(r.err.trimmed().count('\n') == 0 && r.err.startsWith("lucerna: "), qPrintable(r.err));
    }
    QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
}

void TestReport::interruptedReportLeavesNoFile() {
    QTemporaryDir dir;
    QProcess p;
    p.start(LUCERNA_BINARY, {"report", kScenes + "office_floor.json", "-o", dir.filePath("r.pdf"), "--error", "0.0001",
                             "--time", "60"});
    QVERIFY(p.waitForStarted());
    QTest::qWait(1500);  // the scene loaded, the grid under way
    QCOMPARE(p.state(), QProcess::Running);
    ::kill(pid_t(p.processId()), SIGINT);
    QVERIFY(p.waitForFinished(10000));
    QCOMPARE(p.exitCode(), 130);
    QVERIFY(QString(p.readAllStandardError()).contains("report interrupted; no file written"));
    QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
}


// File > Export Report: the dialog's path, a progress dialog while it computes, the PDF written,
// a line in the status bar; the figures those of the command line.
void TestReport::exportReportFromWindow() {
    REQUIRE_POPPLER();
    QTemporaryDir dir;
    const QString scene = writeProjectScene(dir);
    MainWindow w(scene);
    w.reportExport()->setSettings(smallSettings());
    const QString pdf = dir.filePath("from-window");  // the suffix is added
    w.fileDialogs()->replace([&](FileDialogs::Mode mode, const QString&, const QString&, const QString& filter) {
        return mode == FileDialogs::Mode::Save && filter.contains("pdf") ? pdf : QString();
    });
    QSignalSpy done(w.reportExport(), &ReportExport::finished);
    test::trigger(w, "actionExportReport");
    QVERIFY(w.reportExport()->isRunning());
    QVERIFY(w.reportExport()->progressDialog() && w.reportExport()->progressDialog()->isVisible());
    QVERIFY(w.grab().save("report_export_window.png"));  // the window with the progress dialog over it
    QVERIFY(w.reportExport()->progressDialog()->grab().save("report_export_progress.png"));
    QVERIFY(done.wait(120000));
    QCOMPARE(done.front().at(0).toBool(), true);
    QVERIFY2(w.statusBar()->currentMessage().startsWith("Wrote from-window.pdf"), qPrintable(w.statusBar()->currentMessage()));
    QVERIFY(!w.reportExport()->progressDialog()->isVisible());
    const QString text = pdfText(pdf + ".pdf");
    QVERIFY(text.contains("Refit of the second floor"));
    QCOMPARE(figureLines(text).front(), gridLine({scene, "--corner", "0.5,0.75,0.5", "--u", "0,0,3", "--v", "2.5,0,0"}));
    QVERIFY(!w.document()->undoStack()->canUndo());  // the document is untouched
}

void TestReport::exportReportCancelAndError() {
    QTemporaryDir dir;
    MainWindow w(kScenes + "office_floor.json");
    ReportSettings slow = smallSettings();
    slow.grid.targetRelativeError = 0.0001;  // runs until cancelled
    w.reportExport()->setSettings(slow);
    QString path = dir.filePath("cancelled.pdf");
    w.fileDialogs()->replace([&](FileDialogs::Mode, const QString&, const QString&, const QString&) { return path; });
    QSignalSpy done(w.reportExport(), &ReportExport::finished);
    test::trigger(w, "actionExportReport");
    QTest::qWait(500);
    QVERIFY(w.reportExport()->isRunning());
    auto* cancel = w.reportExport()->progressDialog()->findChild<QPushButton*>();
    QVERIFY(cancel);
    QTest::mouseClick(cancel, Qt::LeftButton);  // the dialog's Cancel button
    QCOMPARE(done.size(), 1);
    QCOMPARE(done.front().at(0).toBool(), false);
    QVERIFY(done.front().at(1).toString().contains("cancelled"));
    QVERIFY(!w.reportExport()->isRunning());
    QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());

    // A folder that does not exist: one line in a message box before any work; no file.
    path = dir.filePath("no/such/folder/r.pdf");
    done.clear();
    test::trigger(w, "actionExportReport");
    QCOMPARE(done.size(), 1);
    QCOMPARE(done.front().at(0).toBool(), false);
    QVERIFY(!w.reportExport()->isRunning());
    auto* box = w.findChild<QMessageBox*>("reportError");
    QVERIFY(box && box->isVisible());
    QVERIFY2(box->text().contains("no such folder") && !box->text().contains('\n'), qPrintable(box->text()));
    box->accept();
    QVERIFY(!QDir(dir.filePath("no")).exists());
}

QTEST_MAIN(TestReport)
#include "test_report.moc"
