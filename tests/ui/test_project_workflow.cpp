// A lighting design made from File > New in the window alone, as a designer makes it (issue 36):
// a room typed into Edit > Add Room, a window in its wall (Edit > Add Opening), the maintenance
// factor (File > Project Settings), two task areas with EN 12464-1 activities (Edit > Add Task
// Area), a 4 x 3 field of luminaires from an IES file (Edit > Arrange Lights) and the new
// scene's own light deleted from the outliner; each task area computed in the Calculation grid
// dock with its checks, and the PDF report exported (File > Export Report). Every edit is one
// undo step. Screenshots of the plan, the window and the dock, and the PDF, go to the working
// folder (project_workflow_*).

#include "ui/calculation/grid_panel.h"
#include "ui/calculation/report_export.h"
#include "ui/io/file_dialogs.h"
#include "ui/plan/plan_view.h"
#include "ui/properties/task_area_fields.h"
#include "ui/scene_panels/arrangement_dialog.h"
#include "ui/scene_panels/maintenance_factor_edit.h"
#include "ui/scene_panels/opening_dialog.h"
#include "ui/scene_panels/outliner.h"
#include "ui/scene_panels/project_dialog.h"
#include "ui/scene_panels/room_dialog.h"
#include "ui/scene_panels/task_area_dialog.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <functional>
#include <set>

using namespace lucerna;
using namespace lucerna::test;

namespace {
constexpr int kTimeout = 120000;  // ms; generous for a loaded machine, never a timing assertion

void typeText(QLineEdit* field, const QString& text) {
    field->setFocus();
    field->selectAll();
    QTest::keyClick(field, Qt::Key_Backspace);
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Tab);
}

// A choice made in a list as a user makes it (activated, not just the index).
void choose(QComboBox* combo, int index) {
    QVERIFY(index >= 0);
    combo->setCurrentIndex(index);
    emit combo->activated(index);
}

void pressOk(QDialog* dialog) {
    QPushButton* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok && ok->isEnabled());
    QTest::mouseClick(ok, Qt::LeftButton);
}

// Triggers the action `name`, runs `fill` on the modal dialog of type D it opens, and returns
// whether the dialog was accepted. A failed check in `fill` leaves the dialog open, which is then
// cancelled so that the test goes on to report the failure.
template <class D> bool throughDialog(MainWindow& w, const char* name, const std::function<void(D*)>& fill) {
    bool accepted = false;
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<D*>(QApplication::activeModalWidget());
        if (!dialog) return;
        dialog->activateWindow();  // a typed field counts when Tab takes the focus away
        if (QTest::qWaitForWindowActive(dialog)) fill(dialog);
        accepted = !dialog->isVisible() && dialog->result() == QDialog::Accepted;
        if (dialog->isVisible()) dialog->reject();
    });
    trigger(w, name);
    return accepted;
}

// A task area typed into Edit > Add Task Area's dialog: plan rectangle (m) and activity.
void fillTaskArea(TaskAreaDialog* dialog, const QString& name, double x, double z, double width, double depth,
                  const QString& reference, bool surrounding) {
    TaskAreaFields* f = dialog->fields();
    typeText(f->nameField(), name);
    typeAndTab(f->xField(), x);
    typeAndTab(f->zField(), z);
    typeAndTab(f->widthField(), width);
    typeAndTab(f->depthField(), depth);
    QComboBox* areas = f->activityAreaField();
    choose(areas, areas->findText("Offices"));
    choose(f->activityField(), f->activityField()->findData(reference));
    if (surrounding) f->surroundingBox()->click();
    pressOk(dialog);
}

// A click on an item of the outliner, as the mouse makes it.
void clickItem(Outliner* outliner, QTreeWidgetItem* item) {
    outliner->scrollToItem(item);
    QTest::mouseClick(outliner->viewport(), Qt::LeftButton, {}, outliner->visualItemRect(item).center());
}

// The room's outline (x, z in metres): 6 x 5 m with the new scene's camera, at z = 6, inside.
const double kCorners[4][2] = {{-3, 1.5}, {3, 1.5}, {3, 6.5}, {-3, 6.5}};
}  // namespace

class TestProjectWorkflow : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_project_workflow"); }

    void designFromFileNew() {
        MainWindow w(cornellPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });  // also when a check fails early
        w.resize(1600, 1000);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTemporaryDir dir;
        const QString ies = QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/luminaires/office_panel.ies");
        const QString pdf = dir.filePath("office report.pdf");
        w.fileDialogs()->replace([&](FileDialogs::Mode mode, const QString&, const QString&, const QString& filter) {
            if (mode == FileDialogs::Mode::Save) return filter.contains("pdf", Qt::CaseInsensitive) ? pdf : QString();
            return filter.contains("ies", Qt::CaseInsensitive) ? ies : QString();
        });
        trigger(w, "actionNew");
        Document* doc = w.document();
        QUndoStack* undo = doc->undoStack();
        const int start = undo->count();

        // The room, typed into Edit > Add Room's dialog.
        QVERIFY(throughDialog<RoomDialog>(w, "actionAddRoom", [](RoomDialog* d) {
            for (int r = 0; r < 4; ++r) {
                typeAndTab(d->cornerField(r, 0), kCorners[r][0]);
                typeAndTab(d->cornerField(r, 1), kCorners[r][1]);
            }
            const QString summary = d->findChild<QLabel*>("roomSummary")->text();
            QVERIFY2(summary.contains("floor 30.00 m²"), qPrintable(summary));
            pressOk(d);
        }));
        QCOMPARE(undo->count(), start + 1);
        QCOMPARE(doc->scene().rooms.size(), size_t(1));
        const std::string room = doc->scene().rooms[0].name;

        // A window in wall 1 (6 m along z = 1.5, which the camera faces), glazed at 70 %.
        QVERIFY(throughDialog<OpeningDialog>(w, "actionAddOpening", [](OpeningDialog* d) {
            QCOMPARE(d->findChild<QComboBox*>("openingType")->currentIndex(), 0);  // a window
            d->findChild<QComboBox*>("openingWall")->setCurrentIndex(0);
            typeAndTab(d->findChild<QDoubleSpinBox*>("openingWidth"), 3);
            typeAndTab(d->findChild<QDoubleSpinBox*>("openingOffset"), 1.5);
            typeAndTab(d->findChild<QDoubleSpinBox*>("openingSill"), 0.9);
            typeAndTab(d->findChild<QDoubleSpinBox*>("openingHeight"), 1.4);
            typeAndTab(d->findChild<QDoubleSpinBox*>("openingTransmittance"), 70);
            pressOk(d);
        }));
        QCOMPARE(undo->count(), start + 2);
        // The height and the walls' reflectance, changed in Edit > Edit Room; the window stays.
        QVERIFY(throughDialog<RoomDialog>(w, "actionEditRoom", [](RoomDialog* d) {
            typeAndTab(d->findChild<QDoubleSpinBox*>("roomHeight"), 2.8);
            typeAndTab(d->findChild<QDoubleSpinBox*>("roomWallReflectance"), 60);
            pressOk(d);
        }));
        QCOMPARE(undo->count(), start + 3);
        QCOMPARE(doc->scene().rooms[0].height, 2.8);
        QCOMPARE(doc->scene().rooms[0].openings.size(), size_t(1));

        // The maintenance factor, one number, in File > Project Settings.
        QVERIFY(throughDialog<ProjectDialog>(w, "actionProjectSettings", [](ProjectDialog* d) {
            typeText(d->findChild<QLineEdit*>("projectName"), "Two-desk office");
            d->tabs()->setCurrentIndex(1);
            auto* edit = d->findChild<MaintenanceFactorEdit*>("sceneMaintenance");
            choose(edit->modeField(), MaintenanceFactorEdit::kNumber);
            typeAndTab(edit->numberField(), 0.8);
            pressOk(d);
        }));
        QCOMPARE(undo->count(), start + 4);
        QVERIFY(doc->scene().maintenance && doc->scene().maintenance->value);
        QCOMPARE(*doc->scene().maintenance->value, 0.8);

        // Two task areas (Ctrl+Alt+T), with activities from EN 12464-1's table.
        QVERIFY(throughDialog<TaskAreaDialog>(w, "actionAddTaskArea", [](TaskAreaDialog* d) {
            fillTaskArea(d, "desk", -2.4, 2.2, 1.8, 1.2, "5.26.2", true);
        }));
        const Scene oneArea = doc->scene();
        QVERIFY(throughDialog<TaskAreaDialog>(w, "actionAddTaskArea", [](TaskAreaDialog* d) {
            fillTaskArea(d, "meeting table", 0.4, 3.6, 2.0, 1.6, "5.26.5", false);
        }));
        QCOMPARE(undo->count(), start + 6);
        QCOMPARE(doc->scene().taskAreas.size(), size_t(2));
        // Undoing the last task area takes just that away; redone, it is back as it was.
        const Scene twoAreas = doc->scene();
        trigger(w, "actionUndo");
        QVERIFY(doc->scene().taskAreas == oneArea.taskAreas);
        QVERIFY(doc->scene().objects == oneArea.objects && doc->scene().lights == oneArea.lights);
        QVERIFY(doc->scene().rooms == oneArea.rooms && doc->scene().maintenance == oneArea.maintenance);
        trigger(w, "actionRedo");
        QVERIFY(doc->scene().taskAreas == twoAreas.taskAreas);

        // 4 x 3 luminaires (Edit > Arrange Lights) from an IES file, over the room, under its ceiling.
        QVERIFY(throughDialog<ArrangementDialog>(w, "actionArrangeLights", [](ArrangementDialog* d) {
            auto* source = d->findChild<QComboBox*>("arrangeSource");
            choose(source, source->findText("Luminaire file (IES, EULUMDAT)"));
            QPushButton* browse = nullptr;
            for (QPushButton* b : d->findChildren<QPushButton*>())
                if (b->text() == "Browse...") browse = b;
            QVERIFY(browse && browse->isEnabled());
            QTest::mouseClick(browse, Qt::LeftButton);
            QVERIFY(d->findChild<QLineEdit*>("arrangeFile")->text().endsWith("office_panel.ies"));
            const char* rect[4] = {"arrangeX0", "arrangeZ0", "arrangeX1", "arrangeZ1"};
            const double values[4] = {-3, 1.5, 3, 6.5};
            for (int k = 0; k < 4; ++k) typeAndTab(d->findChild<QDoubleSpinBox*>(rect[k]), values[k]);
            d->findChild<QRadioButton*>("arrangeByCount")->click();
            typeAndTab(d->findChild<QSpinBox*>("arrangeColumns"), 4);
            typeAndTab(d->findChild<QSpinBox*>("arrangeRows"), 3);
            QCOMPARE(d->findChild<QDoubleSpinBox*>("arrangeCeiling")->value(), 2.8);  // the room's ceiling
            typeAndTab(d->findChild<QDoubleSpinBox*>("arrangeSuspension"), 0.01);
            const QString summary = d->findChild<QLabel*>("arrangeSummary")->text();
            QVERIFY2(summary.startsWith("4 x 3 = 12 lights"), qPrintable(summary));
            pressOk(d);
        }));
        QCOMPARE(undo->count(), start + 7);
        // The new scene's own point light, clicked in the outliner and deleted.
        Outliner* outliner = w.outliner();
        QTreeWidgetItem* point = outliner->lightItem(0);
        QVERIFY(point && point->text(0) == "point");
        clickItem(outliner, point);
        QCOMPARE(outliner->selection().kind, Outliner::Kind::Light);
        trigger(w, "actionDelete");
        QCOMPARE(undo->count(), start + 8);

        // What the scene now holds: the room's surfaces and window, two areas, 12 luminaires.
        const Scene& s = doc->scene();
        QCOMPARE(s.rooms.size(), size_t(1));
        QCOMPARE(s.rooms[0].openings.size(), size_t(1));
        QVERIFY(s.rooms[0].outline == (PlanPolygon{{-3, 1.5}, {3, 1.5}, {3, 6.5}, {-3, 6.5}}));
        const RoomOpening& window = s.rooms[0].openings[0];
        QVERIFY(window.type == OpeningType::Window && window.wall == 1 && window.width == 3 && window.offset == 1.5);
        QCOMPARE(s.objects.size(), size_t(7));  // floor, ceiling, four walls and the pane
        std::set<std::string> names;
        for (const Object& o : s.objects) {
            QCOMPARE(o.room, room);
            names.insert(o.name);
        }
        for (const char* part : {" floor", " ceiling", " wall 1", " wall 2", " wall 3", " wall 4", " window 1"})
            QVERIFY2(names.count(room + part), part);
        QCOMPARE(s.findMaterial(room + " walls")->albedo, Rgbd(0.6, 0.6, 0.6));
        const Material* glazing = s.findMaterial(s.rooms[0].openings[0].glazing);
        QVERIFY(glazing && glazing->type == MaterialType::Glazing && glazing->transmittance == Rgbd(0.7, 0.7, 0.7));
        QCOMPARE(s.taskAreas[0].grid.name, std::string("desk"));
        QCOMPARE(s.taskAreas[1].grid.name, std::string("meeting table"));
        QCOMPARE(s.taskAreas[0].activity, std::string("5.26.2"));
        QCOMPARE(s.taskAreas[1].activity, std::string("5.26.5"));
        QVERIFY(s.taskAreas[0].surroundingMeters && !s.taskAreas[1].surroundingMeters);
        QCOMPARE(s.lights.size(), size_t(12));
        for (const Light& l : s.lights) {
            QCOMPARE(l.type, LightType::Luminaire);
            QVERIFY(l.position.y > 2.7 && l.position.y < 2.8);
            QVERIFY(l.position.x > -3 && l.position.x < 3 && l.position.z > 1.5 && l.position.z < 6.5);
        }

        // The plan: room, window, task areas and luminaires.
        trigger(w, "actionViewPlan");
        QTest::qWait(100);
        w.planView()->fitToScene();
        QTest::qWait(100);
        QVERIFY(w.planView()->grab().save("project_workflow_plan.png"));

        // Each task area computed in the Calculation grid dock: Em checked against its activity.
        w.findChild<QDockWidget*>("gridDock")->raise();
        GridPanel* panel = w.gridPanel();
        auto* areaList = child<QComboBox>(*panel, "gridTaskArea");
        QCOMPARE(areaList->count(), 3);  // the work plane, then the two areas
        choose(child<QComboBox>(*panel, "gridMethod"), child<QComboBox>(*panel, "gridMethod")->findText("path"));
        typeAndTab(child<QDoubleSpinBox>(*panel, "gridTarget"), 10);
        const QString references[2] = {" 5.26.2, Offices: ", " 5.26.5, Offices: "};
        for (int i = 0; i < 2; ++i) {
            choose(areaList, i + 1);
            QTest::mouseClick(child<QPushButton>(*panel, "gridCompute"), Qt::LeftButton);
            QTRY_VERIFY_WITH_TIMEOUT(!panel->isComputing(), kTimeout);
            QVERIFY(panel->result() && !panel->result()->lux.empty());
            const QString figures = child<QLabel>(*panel, "gridFigures")->text();
            QVERIFY2(figures.contains(references[i]), qPrintable(figures));
            const QRegularExpression em(R"(\n  Em [0-9]+ lx \+- [0-9.e+-]+ lx >= 500 lx: (met|borderline|not met)\b)");
            QVERIFY2(em.match(figures).hasMatch(), qPrintable(figures));
            QVERIFY2(!figures.contains("not checked: no maintenance factor"), qPrintable(figures));
            if (i == 0) {  // the desk's surrounding zone, with its own requirement and checks
                QVERIFY2(figures.contains("required (EN 12464-1, task Em 500 lx): Em 300 lx, U0 0.40"), qPrintable(figures));
                const QRegularExpression zoneEm(R"(\n  Em [0-9]+ lx \+- [0-9.e+-]+ lx >= 300 lx: (met|borderline|not met)\b)");
                QVERIFY2(zoneEm.match(figures).hasMatch(), qPrintable(figures));
            }
            // At the window's size the figures scroll in their pane and the table of values
            // shows its header and three rows at least within the dock (the text once pressed it
            // to a strip a few pixels tall).
            auto* table = child<QTableWidget>(*panel, "gridTable");
            QVERIFY(table->rowCount() >= 3);
            const int shownHeight = table->visibleRegion().boundingRect().height();
            const int needed = table->horizontalHeader()->height() + 3 * table->rowHeight(0);
            QVERIFY2(shownHeight >= needed, qPrintable(QString("the table shows %1 px of %2").arg(shownHeight).arg(needed)));
            auto* figuresPane = child<QScrollArea>(*panel, "gridFiguresScroll");
            QVERIFY(figuresPane->viewport()->height() >= 4 * figuresPane->fontMetrics().lineSpacing());
            QVERIFY(figuresPane->verticalScrollBar()->maximum() > 0);  // its thirty lines and more scroll there
            QVERIFY(w.findChild<QDockWidget*>("gridDock")->grab().save(QString("project_workflow_dock_%1.png").arg(i + 1)));
        }
        QVERIFY(w.grab().save("project_workflow_window.png"));

        // The report, File > Export Report, to a PDF of several pages. Its camera render is
        // lighter than the default (the window offers no report settings: set as test_report does);
        // the grids, glare and checks are computed as the window computes them.
        ReportSettings lighter = w.reportExport()->settings();
        lighter.renderSpp = 8;
        w.reportExport()->setSettings(lighter);
        QSignalSpy done(w.reportExport(), &ReportExport::finished);
        QElapsedTimer clock;
        clock.start();
        trigger(w, "actionExportReport");
        QVERIFY(w.reportExport()->isRunning());
        QVERIFY(done.wait(kTimeout * 3));
        qInfo("the report took %lld ms", clock.elapsed());
        QVERIFY2(done.front().at(0).toBool(), qPrintable(done.front().at(1).toString()));
        const QRegularExpression wrote(R"(^Wrote office report\.pdf \(([0-9]+) pages\))");
        const QRegularExpressionMatch m = wrote.match(done.front().at(1).toString());
        QVERIFY2(m.hasMatch(), qPrintable(done.front().at(1).toString()));
        QVERIFY2(m.captured(1).toInt() >= 3, qPrintable(m.captured(0)));
        QFile file(pdf);
        QVERIFY(file.open(QIODevice::ReadOnly) && file.read(5) == "%PDF-");
        QFile::remove("project_workflow_report.pdf");
        QVERIFY(QFile::copy(pdf, "project_workflow_report.pdf"));
        // The page text names both areas (poppler-utils: packaging/install-deps.sh installs it).
        QProcess p;
        p.start("pdftotext", {pdf, "-"});
        QVERIFY2(p.waitForFinished(30000) && p.exitCode() == 0, "pdftotext (poppler-utils) failed or is missing");
        const QString text = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(text.contains("desk") && text.contains("meeting table"), qPrintable(text.left(2000)));
        QCOMPARE(undo->count(), start + 8);  // computing and reporting changed nothing
    }
};

QTEST_MAIN(TestProjectWorkflow)
#include "test_project_workflow.moc"
