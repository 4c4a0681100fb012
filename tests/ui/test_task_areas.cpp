// Task areas made and edited in the window (README, "Task areas"): one drawn in the plan with two
// corner clicks and completed in the dialog (name, activity, work-plane height, surrounding
// zone), seen in the outliner, the plan and the Calculation grid dock's list, edited on its
// properties page, refused an empty name, deleted, each step one undo step and undone; one given
// numerically through Edit > Add Task Area with both zones, computed in the dock with its zones'
// figures and checks. Screenshots of the dialog and of the plan with both areas.

#include "core/photometry/lighting_standards.h"
#include "core/photometry/plan_rectangle.h"
#include "core/photometry/surrounding_zones.h"
#include "core/scene/scene_geometry.h"
#include "ui/calculation/grid_panel.h"
#include "ui/plan/plan_view.h"
#include "ui/properties/properties_panel.h"
#include "ui/properties/task_area_fields.h"
#include "ui/properties/task_area_properties.h"
#include "ui/scene_panels/outliner.h"
#include "ui/scene_panels/task_area_dialog.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QToolButton>
#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {
constexpr int kTimeout = 60000;  // ms; generous for a loaded machine, never a timing assertion

void typeText(QLineEdit* field, const QString& text) {
    field->setFocus();
    field->selectAll();
    QTest::keyClick(field, Qt::Key_Backspace);
    QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Return);
}

// Chooses an activity as a user does: its area, then the activity by its reference.
void chooseActivity(TaskAreaFields* f, const QString& area, const QString& reference) {
    QComboBox* areas = f->activityAreaField();
    const int a = areas->findText(area);
    QVERIFY(a > 0);
    areas->setCurrentIndex(a);
    emit areas->activated(a);
    QComboBox* activities = f->activityField();
    const int i = activities->findData(reference);
    QVERIFY(i >= 0);
    activities->setCurrentIndex(i);
    emit activities->activated(i);
}

void pressOk(QDialog* dialog) {
    QPushButton* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isEnabled());
    QTest::mouseClick(ok, Qt::LeftButton);
}

PlanRectangle rectangleOf(const Document* doc, int i) { return *planRectangle(doc->scene().taskAreas.at(size_t(i)).grid); }
}  // namespace

class TestTaskAreas : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_task_areas"); }

    void drawEditDeleteAndUndo() {
        MainWindow w(cornellPath());
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        trigger(w, "actionNew");  // a 10 m floor in metres, from -5 to 5
        trigger(w, "actionViewPlan");
        Document* doc = w.document();
        QUndoStack* undo = doc->undoStack();
        PlanView* plan = w.planView();
        QTest::qWait(100);
        plan->fitToScene();
        const int start = undo->count();

        // Drawn in the plan: two corner clicks, then the dialog over that rectangle.
        QTest::mouseClick(plan->drawTaskAreaButton(), Qt::LeftButton);
        QVERIFY(plan->drawTaskAreaButton()->isChecked());
        click(plan, plan->widgetOf(V3d(1, 0, 1)));
        QVERIFY(plan->drawTaskAreaButton()->isChecked());  // waiting for the opposite corner
        bool filled = false;
        QTimer::singleShot(0, [&] {
            auto* dialog = qobject_cast<TaskAreaDialog*>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            TaskAreaFields* f = dialog->fields();
            QCOMPARE(f->xField()->value(), 1.0);
            QCOMPARE(f->zField()->value(), 1.0);
            QCOMPARE(f->widthField()->value(), 2.0);
            QCOMPARE(f->depthField()->value(), 1.0);
            QCOMPARE(f->heightField()->value(), 0.8);  // the work plane's usual height
            QVERIFY2(f->spacingField()->specialValueText().contains("EN 12464-1: 0.32 m"),
                     qPrintable(f->spacingField()->specialValueText()));
            f->nameField()->setFocus();
            f->nameField()->selectAll();
            QTest::keyClicks(f->nameField(), "desk");
            QTest::keyClick(f->nameField(), Qt::Key_Tab);
            chooseActivity(f, "Offices", "5.26.2");
            QCOMPARE(dialog->findChild<QLabel*>("taskAreaRequirement")->text(),
                     QString::fromStdString(describeRequirement(*findActivity("5.26.2", StandardEdition::En12464_2021))));
            typeAndTab(f->heightField(), 0.75);
            f->surroundingBox()->click();
            QVERIFY(f->surroundingBox()->isChecked() && f->surroundingWidthField()->isEnabled());
            QVERIFY(dialog->findChild<QLabel*>("taskAreaSurroundingNote")->text().contains("Em 300 lx, U0 0.40"));
            QVERIFY(f->backgroundBox()->isEnabled() && !f->backgroundBox()->isChecked());
            QCoreApplication::processEvents();  // laid out as shown
            dialog->grab().save("task_area_dialog.png");
            filled = true;
            pressOk(dialog);
        });
        click(plan, plan->widgetOf(V3d(3, 0, 2)));
        QVERIFY(filled);
        QVERIFY(!plan->drawTaskAreaButton()->isChecked());
        QCOMPARE(doc->scene().taskAreas.size(), size_t(1));
        const TaskArea drawn = doc->scene().taskAreas[0];
        QCOMPARE(drawn.grid.name, std::string("desk"));
        QCOMPARE(drawn.activity, std::string("5.26.2"));
        QCOMPARE(rectangleOf(doc, 0), (PlanRectangle{1, 1, 2, 1, 0.75}));
        QCOMPARE(drawn.grid.normal(), V3d(0, 1, 0));
        QCOMPARE(*drawn.surroundingMeters, 0.5);
        QVERIFY(!drawn.backgroundMeters && !drawn.grid.spacingMeters && drawn.observers.empty());
        QCOMPARE(undo->count(), start + 1);

        // In the outliner (selected), the plan, the properties page and the dock's list.
        Outliner* outliner = w.outliner();
        QTreeWidgetItem* heading = outliner->heading(Outliner::Kind::TaskArea);
        QVERIFY(heading);
        QCOMPARE(heading->text(0), QString("Task areas"));
        QCOMPARE(heading->childCount(), 1);
        QCOMPARE(heading->child(0)->text(0), QString("desk"));
        QCOMPARE(heading->child(0)->text(1), QString("Task area, 5.26.2"));
        QCOMPARE(outliner->selection().kind, Outliner::Kind::TaskArea);
        QCOMPARE(plan->selectedTaskArea(), 0);
        TaskAreaProperties* page = w.propertiesPanel()->taskAreaProperties();
        QCOMPARE(w.propertiesPanel()->currentWidget(), static_cast<QWidget*>(page));
        TaskAreaFields* f = page->fields();
        QCOMPARE(f->nameField()->text(), QString("desk"));
        QCOMPARE(f->heightField()->value(), 0.75);
        QVERIFY(f->surroundingBox()->isChecked());
        auto* dockList = child<QComboBox>(*w.gridPanel(), "gridTaskArea");
        QCOMPARE(dockList->count(), 2);
        QCOMPARE(dockList->itemText(1), QString("desk (5.26.2)"));

        // Edited on the page: each field one undo step.
        typeInto(f->widthField(), 2.5);
        QCOMPARE(rectangleOf(doc, 0), (PlanRectangle{1, 1, 2.5, 1, 0.75}));
        QCOMPARE(undo->count(), start + 2);
        chooseActivity(f, "Offices", "5.26.3");
        QCOMPARE(doc->scene().taskAreas[0].activity, std::string("5.26.3"));
        QCOMPARE(undo->count(), start + 3);
        typeText(f->nameField(), "drawing desk");
        QCOMPARE(doc->scene().taskAreas[0].grid.name, std::string("drawing desk"));
        QCOMPARE(undo->count(), start + 4);
        QCOMPARE(outliner->heading(Outliner::Kind::TaskArea)->child(0)->text(0), QString("drawing desk"));
        QCOMPARE(dockList->itemText(1), QString("drawing desk (5.26.3)"));
        QCOMPARE(w.propertiesPanel()->currentWidget(), static_cast<QWidget*>(page));  // still selected
        // An observer added (the first default one: the middle of the first side, eyes at 1.2 m).
        QTest::mouseClick(f->addObserverButton(), Qt::LeftButton);
        QCOMPARE(undo->count(), start + 5);
        QCOMPARE(doc->scene().taskAreas[0].observers.size(), size_t(1));
        QCOMPARE(doc->scene().taskAreas[0].observers[0].position.y, 1.2);
        QCOMPARE(f->observersTable()->rowCount(), 1);
        // An empty name is refused, with its reason, and changes nothing.
        typeText(f->nameField(), "");
        QCOMPARE(doc->scene().taskAreas[0].grid.name, std::string("drawing desk"));
        QCOMPARE(undo->count(), start + 5);
        QVERIFY2(page->problem().contains("needs a name"), qPrintable(page->problem()));
        QCOMPARE(f->nameField()->text(), QString("drawing desk"));

        // Undone step by step, the page following.
        undo->undo();
        QVERIFY(doc->scene().taskAreas[0].observers.empty());
        QCOMPARE(f->observersTable()->rowCount(), 0);
        undo->undo();
        QCOMPARE(doc->scene().taskAreas[0].grid.name, std::string("desk"));
        QCOMPARE(f->nameField()->text(), QString("desk"));
        undo->undo();
        QCOMPARE(doc->scene().taskAreas[0].activity, std::string("5.26.2"));
        QCOMPARE(f->activityField()->currentData().toString(), QString("5.26.2"));
        undo->undo();
        QCOMPARE(rectangleOf(doc, 0), (PlanRectangle{1, 1, 2, 1, 0.75}));
        QCOMPARE(f->widthField()->value(), 2.0);
        QVERIFY(doc->scene().taskAreas[0] == drawn);

        // Selected by a click in the plan, deleted with Delete, and back with Undo.
        outliner->clearSelection();
        QCOMPARE(plan->selectedTaskArea(), -1);
        click(plan, plan->widgetOf(V3d(2, 0.75, 1.5)));
        QCOMPARE(outliner->selection().kind, Outliner::Kind::TaskArea);
        QCOMPARE(outliner->selection().index, 0);
        QCOMPARE(plan->selectedTaskArea(), 0);
        trigger(w, "actionDelete");
        QVERIFY(doc->scene().taskAreas.empty());
        QCOMPARE(outliner->heading(Outliner::Kind::TaskArea)->childCount(), 0);
        QCOMPARE(dockList->count(), 1);
        QCOMPARE(undo->count(), start + 2);  // the add and the delete: the edits were undone
        undo->undo();
        QCOMPARE(doc->scene().taskAreas.size(), size_t(1));
        QVERIFY(doc->scene().taskAreas[0] == drawn);
        QCOMPARE(dockList->count(), 2);
        undo->undo();  // the drawing itself
        QVERIFY(doc->scene().taskAreas.empty());
        undo->redo();
        QVERIFY(doc->scene().taskAreas[0] == drawn);

        // A second one given numerically (Edit > Add Task Area), with both zones.
        filled = false;
        QTimer::singleShot(0, [&] {
            auto* dialog = qobject_cast<TaskAreaDialog*>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            TaskAreaFields* g = dialog->fields();
            QCOMPARE(g->nameField()->text(), QString("task area 2"));
            typeAndTab(g->xField(), -3);
            typeAndTab(g->zField(), -2.5);
            typeAndTab(g->widthField(), 3);
            typeAndTab(g->depthField(), 2);
            chooseActivity(g, "Educational buildings", "5.36.3");
            g->surroundingBox()->click();
            g->backgroundBox()->click();
            QVERIFY(g->backgroundWidthField()->isEnabled());
            QCOMPARE(g->backgroundWidthField()->value(), 3.0);
            QVERIFY(dialog->findChild<QLabel*>("taskAreaBackgroundNote")->text().contains("Em 67 lx, U0 0.10"));
            filled = true;
            pressOk(dialog);
        });
        trigger(w, "actionAddTaskArea");
        QVERIFY(filled);
        QCOMPARE(doc->scene().taskAreas.size(), size_t(2));
        const TaskArea& second = doc->scene().taskAreas[1];
        QCOMPARE(rectangleOf(doc, 1), (PlanRectangle{-3, -2.5, 3, 2, 0.8}));
        QCOMPARE(*second.surroundingMeters, 0.5);
        QCOMPARE(*second.backgroundMeters, 3.0);
        QCOMPARE(outliner->selection().index, 1);
        QTest::qWait(100);
        plan->grab().save("task_areas_plan.png");
        QImage image = plan->grab().toImage();
        // The outline is drawn where the area's corner is (within a pixel or two).
        const QPoint corner = plan->widgetOf(V3d(1, 0.75, 2)).toPoint();
        bool outlined = false;
        for (int dx = -2; dx <= 2; ++dx)
            for (int dy = -2; dy <= 2; ++dy) {
                const QColor c = image.pixelColor(corner + QPoint(dx, dy));
                outlined = outlined || (c.green() > c.red() + 40 && c.green() > c.blue());
            }
        QVERIFY(outlined);

        // Computed in the dock: the task area's own grid, then its zones' figures and checks.
        w.findChild<QDockWidget*>("gridDock")->raise();
        GridPanel* panel = w.gridPanel();
        dockList->setCurrentIndex(2);
        emit dockList->activated(2);
        auto* method = child<QComboBox>(*panel, "gridMethod");
        method->setCurrentIndex(method->findText("path"));
        child<QDoubleSpinBox>(*panel, "gridTarget")->setValue(10);
        QTest::mouseClick(child<QPushButton>(*panel, "gridCompute"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!panel->isComputing(), kTimeout);
        QCOMPARE(panel->layout().points, layoutGrid(second.grid, 1.0).points);
        QCOMPARE(panel->result()->lux.size(), panel->layout().points.size());
        const QString figures = child<QLabel>(*panel, "gridFigures")->text();
        const SceneBounds room = sceneBounds(doc->scene());
        const TaskAreaZones zones = taskAreaZones(second, 1.0, room.lo, room.hi);
        QVERIFY2(figures.contains(QString("surrounding zone (0.5 m, %1 points): Eavg ").arg(zones.surrounding->points.size())),
                 qPrintable(figures));
        QVERIFY2(figures.contains(QString("background area (3 m, %1 points): Eavg ").arg(zones.background->points.size())),
                 qPrintable(figures));
        QVERIFY2(figures.contains("required (EN 12464-1, task Em 300 lx): Em 200 lx, U0 0.40"), qPrintable(figures));
        QVERIFY2(figures.contains("required (EN 12464-1, task Em 300 lx): Em 67 lx, U0 0.10"), qPrintable(figures));
        // No maintenance factor in File > New's scene: Em is not checked, U0 is.
        const QRegularExpression em(R"(\n  Em [0-9]+ lx \+- [0-9.e+-]+ lx >= 200 lx: not checked: no maintenance factor)");
        const QRegularExpression u0(R"(\n  U0 [0-9.]+ \+- [0-9.e+-]+ >= 0.40: (met|borderline|not met))");
        QVERIFY2(em.match(figures).hasMatch() && u0.match(figures).hasMatch(), qPrintable(figures));
        w.grab().save("task_areas_window.png");
        w.setSaveQuestion([] { return QMessageBox::Discard; });
    }
};

QTEST_MAIN(TestTaskAreas)
#include "test_task_areas.moc"
