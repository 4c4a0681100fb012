// File > Project Settings, clicked through as a designer would: the project's name, client,
// designer and notes and the scene's maintenance factor (none, one number or CIE 97's four
// factors, once filled by the assistant) are set by one OK, one undo step; undo restores the
// scene; Cancel changes nothing; setting none says that Em is left unchecked. The light panel's
// own maintenance factor: the scene's, or one number, one undo step per edit. The Standard tab's
// EN 12464-1 edition, in the same undo step as the rest, followed by the task area's page.
// Screenshots of the dialog, the assistant and the light panel go to the working directory.

#include "core/photometry/maintenance_assistant.h"
#include "core/scene/scene_io.h"
#include "ui/properties/light_properties.h"
#include "ui/properties/properties_panel.h"
#include "ui/properties/task_area_fields.h"
#include "ui/properties/task_area_properties.h"
#include "ui/scene_panels/maintenance_assistant_dialog.h"
#include "ui/scene_panels/maintenance_factor_edit.h"
#include "ui/scene_panels/outliner.h"
#include "ui/scene_panels/project_dialog.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTabWidget>
#include <QTimer>
#include <QtTest>

#include <cmath>
#include <functional>

using namespace lucerna;
using namespace lucerna::test;

namespace {

QString interiorPath() { return QStringLiteral(LUCERNA_RESOURCE_DIR "/scenes/interior.json"); }

void typeText(QWidget* field, const QString& text) {
    field->setFocus();
    QTest::keyClicks(field, text);
}

// A choice made in a list as a user makes it (activated, not just the index).
void choose(QComboBox* combo, int index) {
    combo->setCurrentIndex(index);
    emit combo->activated(index);
}

void press(QDialog* dialog, QDialogButtonBox::StandardButton which) {
    QTest::mouseClick(dialog->findChild<QDialogButtonBox*>()->button(which), Qt::LeftButton);
}

// Runs `fill` on the modal dialog of type D that `open` opens, active (a typed field counts when
// Tab takes the focus away); `fill` closes it, or a failed check in it leaves the dialog, which is
// then cancelled so that the test goes on to report the failure.
template <class D> bool withDialog(const std::function<void()>& open, const std::function<void(D*)>& fill) {
    bool ran = false;
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<D*>(QApplication::activeModalWidget());
        if (!dialog) return;
        dialog->activateWindow();
        if (QTest::qWaitForWindowActive(dialog)) {
            ran = true;
            fill(dialog);
        }
        if (dialog->isVisible()) dialog->reject();
    });
    open();
    return ran;
}

// File > Project Settings, with `fill` run on the dialog.
void withProjectDialog(MainWindow& w, const std::function<void(ProjectDialog*)>& fill) {
    QVERIFY(withDialog<ProjectDialog>([&] { trigger(w, "actionProjectSettings"); }, fill));
}

MaintenanceFactorEdit* sceneFactorEdit(ProjectDialog* dialog) {
    return dialog->findChild<MaintenanceFactorEdit*>("sceneMaintenance");
}

bool near(double a, double b) { return std::abs(a - b) < 1e-12; }

}  // namespace

class TestProjectSettings : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_project_settings"); }

    // Both tabs filled, OK: one undo step sets both keys; undo restores the scene's none.
    void projectAndFactorsAreOneStep() {
        MainWindow w(interiorPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        w.show();
        QVERIFY(!w.document()->scene().project && !w.document()->scene().maintenance);
        const int steps = w.document()->undoStack()->count();
        withProjectDialog(w, [](ProjectDialog* dialog) {
            typeText(dialog->findChild<QLineEdit*>("projectName"), "Refit of the second floor");
            typeText(dialog->findChild<QLineEdit*>("projectClient"), "Acme Insurance Ltd");
            typeText(dialog->findChild<QLineEdit*>("projectDesigner"), "J. Doe");
            typeText(dialog->findChild<QPlainTextEdit*>("projectNotes"), "Ceiling 3.00 m");
            QCoreApplication::processEvents();  // laid out as shown
            QVERIFY(dialog->grab().save("project_dialog_project.png"));
            dialog->tabs()->setCurrentIndex(1);
            MaintenanceFactorEdit* edit = sceneFactorEdit(dialog);
            choose(edit->modeField(), MaintenanceFactorEdit::kFactors);
            const auto& f = edit->factorFields();
            typeAndTab(f[0], 0.9);
            typeAndTab(f[2], 0.95);
            typeAndTab(f[3], 0.94);
            QVERIFY(edit->summary()->text().contains("0.804"));  // 0.9 x 1 x 0.95 x 0.94
            QCoreApplication::processEvents();  // laid out as shown
            QVERIFY(dialog->grab().save("project_dialog_maintenance.png"));
            press(dialog, QDialogButtonBox::Ok);
        });
        const Scene& s = w.document()->scene();
        QVERIFY(s.project);
        QCOMPARE(s.project->name, std::string("Refit of the second floor"));
        QCOMPARE(s.project->client, std::string("Acme Insurance Ltd"));
        QCOMPARE(s.project->designer, std::string("J. Doe"));
        QCOMPARE(s.project->notes, std::string("Ceiling 3.00 m"));
        QVERIFY(s.maintenance && !s.maintenance->value);
        QCOMPARE(*s.maintenance->lampLumenMaintenance, 0.9);
        QCOMPARE(*s.maintenance->lampSurvival, 1.0);
        QCOMPARE(*s.maintenance->luminaireMaintenance, 0.95);
        QCOMPARE(*s.maintenance->roomSurfaceMaintenance, 0.94);
        QVERIFY(maintenanceRange(s).maintained());
        QCOMPARE(w.document()->undoStack()->count(), steps + 1);
        w.document()->undoStack()->undo();
        QVERIFY(!w.document()->scene().project && !w.document()->scene().maintenance);
        w.document()->undoStack()->redo();
        QCOMPARE(w.document()->scene().project->client, std::string("Acme Insurance Ltd"));

        // Opened again on what the scene has; OK without a change is no step.
        withProjectDialog(w, [](ProjectDialog* dialog) {
            QCOMPARE(dialog->findChild<QLineEdit*>("projectDesigner")->text(), QString("J. Doe"));
            QCOMPARE(sceneFactorEdit(dialog)->modeField()->currentIndex(), int(MaintenanceFactorEdit::kFactors));
            press(dialog, QDialogButtonBox::Ok);
        });
        QCOMPARE(w.document()->undoStack()->count(), steps + 1);
    }

    // Cancel after typing: the scene and the undo history as they were.
    void cancelChangesNothing() {
        MainWindow w(interiorPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        w.show();
        const Scene before = w.document()->scene();
        const int steps = w.document()->undoStack()->count();
        withProjectDialog(w, [](ProjectDialog* dialog) {
            typeText(dialog->findChild<QLineEdit*>("projectName"), "Not kept");
            dialog->tabs()->setCurrentIndex(1);
            choose(sceneFactorEdit(dialog)->modeField(), MaintenanceFactorEdit::kNumber);
            typeAndTab(sceneFactorEdit(dialog)->numberField(), 0.7);
            press(dialog, QDialogButtonBox::Cancel);
        });
        QVERIFY(w.document()->scene() == before);
        QCOMPARE(w.document()->undoStack()->count(), steps);
    }

    // One number, then none: none says Em is left unchecked, and the scene has no factor again.
    void oneNumberThenNone() {
        MainWindow w(interiorPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        w.show();
        withProjectDialog(w, [](ProjectDialog* dialog) {
            dialog->tabs()->setCurrentIndex(1);
            QVERIFY(dialog->findChild<QLabel*>("maintenanceHelp")->text().contains("\"not checked\""));
            MaintenanceFactorEdit* edit = sceneFactorEdit(dialog);
            QVERIFY(edit->summary()->text().contains("Em is not checked"));
            choose(edit->modeField(), MaintenanceFactorEdit::kNumber);
            typeAndTab(edit->numberField(), 0.8);
            press(dialog, QDialogButtonBox::Ok);
        });
        QVERIFY(w.document()->scene().maintenance);
        QCOMPARE(*w.document()->scene().maintenance->value, 0.8);
        QVERIFY(!w.document()->scene().project);  // the Project tab left empty: no key
        withProjectDialog(w, [](ProjectDialog* dialog) {
            dialog->tabs()->setCurrentIndex(1);
            MaintenanceFactorEdit* edit = sceneFactorEdit(dialog);
            QCOMPARE(edit->numberField()->value(), 0.8);
            choose(edit->modeField(), MaintenanceFactorEdit::kAbsent);
            QVERIFY(edit->summary()->text().contains("Em is not checked"));
            press(dialog, QDialogButtonBox::Ok);
        });
        QVERIFY(!w.document()->scene().maintenance);
        QVERIFY(!maintenanceRange(w.document()->scene()).maintained());
        w.document()->undoStack()->undo();
        QCOMPARE(*w.document()->scene().maintenance->value, 0.8);
    }

    // The assistant: an LED rated L80 at 50,000 h after 25,000 h gives LLMF 0.9, spot replacement
    // LSF 1; LMF and RSMF are not bundled and keep the fields' values, which are then typed.
    void throughTheAssistant() {
        MainWindow w(interiorPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        w.show();
        withProjectDialog(w, [](ProjectDialog* dialog) {
            dialog->tabs()->setCurrentIndex(1);
            MaintenanceFactorEdit* edit = sceneFactorEdit(dialog);
            bool assisted = false;
            const auto open = [&] { QTest::mouseClick(edit->assistantButton(), Qt::LeftButton); };
            withDialog<MaintenanceAssistantDialog>(open, [&](MaintenanceAssistantDialog* assistant) {
                auto* lamp = assistant->findChild<QComboBox*>("assistantLamp");
                lamp->setCurrentIndex(lamp->findData(QString(kLedLamp)));
                typeAndTab(assistant->findChild<QDoubleSpinBox*>("assistantLedRating"), 80);
                typeAndTab(assistant->findChild<QDoubleSpinBox*>("assistantLedLife"), 50000);
                typeAndTab(assistant->findChild<QDoubleSpinBox*>("assistantHours"), 25000);
                assistant->findChild<QCheckBox*>("assistantSpotReplacement")->setChecked(true);
                typeAndTab(assistant->findChild<QDoubleSpinBox*>("assistantRoomLength"), 10);
                typeAndTab(assistant->findChild<QDoubleSpinBox*>("assistantRoomWidth"), 8);
                typeAndTab(assistant->findChild<QDoubleSpinBox*>("assistantMountingHeight"), 2);
                QCOMPARE(assistant->findChild<QLabel*>("assistantRoomIndex")->text(), QString("K = 2.22"));
                const QString result = assistant->findChild<QLabel*>("assistantResult")->text();
                QVERIFY(result.contains("LLMF 0.9: LED rated L80 at 50000 h"));
                QVERIFY(result.contains("LMF not found"));
                QCoreApplication::processEvents();  // laid out as shown
                QVERIFY(assistant->grab().save("maintenance_assistant.png"));
                assisted = true;
                press(assistant, QDialogButtonBox::Ok);
            });
            QVERIFY(assisted);
            QCOMPARE(edit->modeField()->currentIndex(), int(MaintenanceFactorEdit::kFactors));
            const auto& f = edit->factorFields();
            QCOMPARE(f[0]->value(), 0.9);
            QCOMPARE(f[1]->value(), 1.0);
            QVERIFY(edit->summary()->text().contains("spot replacement"));
            QVERIFY(edit->summary()->text().contains("(kept: 1)"));
            QCoreApplication::processEvents();  // laid out as shown
            QVERIFY(dialog->grab().save("project_dialog_assisted.png"));
            dialog->activateWindow();  // back from the assistant
            QVERIFY(QTest::qWaitForWindowActive(dialog));
            typeAndTab(f[2], 0.9);
            typeAndTab(f[3], 0.95);
            press(dialog, QDialogButtonBox::Ok);
        });
        const std::optional<MaintenanceFactor>& mf = w.document()->scene().maintenance;
        QVERIFY(mf);
        QVERIFY(near(*mf->lampLumenMaintenance, 0.9));
        QCOMPARE(*mf->lampSurvival, 1.0);
        QCOMPARE(*mf->luminaireMaintenance, 0.9);
        QCOMPARE(*mf->roomSurfaceMaintenance, 0.95);
        QVERIFY(std::abs(mf->factor() - 0.9 * 0.9 * 0.95) < 1e-12);
    }

    // The Standard tab: absent, the scene is checked against 2021 (an activity its bundled table
    // lacks says it falls back to 2011); 2011 chosen with a project name is one step, written to
    // the file, undone as one; the selected task area's page follows each change.
    void editionIsOneStepWithTheRest() {
        MainWindow w(interiorPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        Document* doc = w.document();
        TaskArea archive;
        archive.grid.name = "filing";
        archive.grid.corner = V3d(0, 0.8, 0);
        archive.grid.edgeU = V3d(1, 0, 0);
        archive.grid.edgeV = V3d(0, 0, -1);
        archive.activity = "5.26.1";  // not among the bundled 2021 entries
        doc->insertTaskArea(0, archive);
        w.outliner()->select(Outliner::Kind::TaskArea, 0);
        TaskAreaFields* f = w.propertiesPanel()->taskAreaProperties()->fields();
        auto* requirement = f->findChild<QLabel*>("taskAreaRequirement");
        const QString filing2011 = "EN 12464-1:2011 5.26.1, Offices: Filing, copying, etc.: Em 300 lx, U0 0.40, UGR_L 19, Ra 80";
        QVERIFY(!doc->scene().lightingStandard);
        QCOMPARE(requirement->text(), filing2011 + " (EN 12464-1:2021 asked; its table here lacks this activity)");
        QCOMPARE(f->activityField()->currentText(), QString("5.26.1 Filing, copying, etc. (2011)"));
        QCOMPARE(f->activityField()->itemText(f->activityField()->findData("5.26.2")),
                 QString("5.26.2 Writing, typing, reading, data processing"));  // bundled: no mark
        const int steps = doc->undoStack()->count();
        withProjectDialog(w, [](ProjectDialog* dialog) {
            QCOMPARE(dialog->tabs()->tabText(2), QString("Standard"));
            dialog->tabs()->setCurrentIndex(2);
            auto* edition = dialog->findChild<QComboBox*>("lightingStandard");
            QCOMPARE(edition->currentText(), QString("EN 12464-1:2021"));  // absent: the default
            const QString help = dialog->findChild<QLabel*>("standardHelp")->text();
            QVERIFY2(help.contains("5.26.2 Writing, typing, reading, data processing") && help.contains("2011 figures"),
                     qPrintable(help));
            QCoreApplication::processEvents();  // laid out as shown
            QVERIFY(dialog->grab().save("project_dialog_standard.png"));
            choose(edition, edition->findText("EN 12464-1:2011"));
            dialog->tabs()->setCurrentIndex(0);
            typeText(dialog->findChild<QLineEdit*>("projectName"), "Archive wing");
            press(dialog, QDialogButtonBox::Ok);
        });
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QVERIFY(doc->scene().lightingStandard == StandardEdition::En12464_2011);
        QCOMPARE(doc->scene().project->name, std::string("Archive wing"));
        QVERIFY(saveSceneToString(doc->scene()).find(R"("lighting_standard": "EN 12464-1:2011")") != std::string::npos);
        QCOMPARE(requirement->text(), filing2011);
        QCOMPARE(f->activityField()->currentText(), QString("5.26.1 Filing, copying, etc."));
        doc->undoStack()->undo();
        QVERIFY(!doc->scene().lightingStandard && !doc->scene().project);
        QVERIFY(requirement->text().endsWith("(EN 12464-1:2021 asked; its table here lacks this activity)"));
        doc->undoStack()->redo();
        QCOMPARE(requirement->text(), filing2011);

        // Back to 2021, now written as chosen; OK without a change is no step.
        withProjectDialog(w, [](ProjectDialog* dialog) {
            auto* edition = dialog->findChild<QComboBox*>("lightingStandard");
            QCOMPARE(edition->currentText(), QString("EN 12464-1:2011"));
            choose(edition, edition->findText("EN 12464-1:2021"));
            press(dialog, QDialogButtonBox::Ok);
        });
        QCOMPARE(doc->undoStack()->count(), steps + 2);
        QVERIFY(doc->scene().lightingStandard == StandardEdition::En12464_2021);
        withProjectDialog(w, [](ProjectDialog* dialog) { press(dialog, QDialogButtonBox::Ok); });
        QCOMPARE(doc->undoStack()->count(), steps + 2);
        // A bundled 2021 entry chosen on the page: its line has the 2021 figures.
        QComboBox* areas = f->activityAreaField();
        choose(areas, areas->findText("Offices"));
        choose(f->activityField(), f->activityField()->findData("5.26.2"));
        QCOMPARE(doc->scene().taskAreas[0].activity, std::string("5.26.2"));
        QVERIFY2(requirement->text().startsWith("EN 12464-1:2021 5.26.2, Offices: Writing, typing, reading, data processing: "
                                                "Em 500 lx (Em,u 1000 lx)") &&
                     requirement->text().endsWith("Eceiling 100 lx (U0 0.10)"),
                 qPrintable(requirement->text()));
        QCoreApplication::processEvents();  // laid out as shown
        QVERIFY(w.propertiesPanel()->grab().save("task_area_page_2021.png"));
    }

    // The light panel: the scene's factor by default; one number is one step, the number typed
    // another; undo goes back through both.
    void lightPanelFactor() {
        MainWindow w(interiorPath());
        w.setSaveQuestion([] { return QMessageBox::Discard; });
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();  // a typed field counts when Tab takes the focus away
        QVERIFY(QTest::qWaitForWindowActive(&w));
        Document* doc = w.document();
        ProjectSettings settings;
        settings.maintenance = MaintenanceFactor{};
        settings.maintenance->value = 0.85;
        doc->setProjectSettings(settings);
        const int pendant = 6;
        QCOMPARE(doc->light(pendant).name, std::string("pendant"));
        w.outliner()->select(Outliner::Kind::Light, pendant);
        MaintenanceFactorEdit* edit = w.lightProperties()->maintenanceField();
        QVERIFY(edit->isVisibleTo(w.lightProperties()));
        QCOMPARE(edit->modeField()->itemText(0), QString("The scene's (0.85)"));
        QCOMPARE(edit->modeField()->currentIndex(), int(MaintenanceFactorEdit::kAbsent));
        const int steps = doc->undoStack()->count();
        choose(edit->modeField(), MaintenanceFactorEdit::kNumber);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QVERIFY(doc->light(pendant).maintenance);
        typeAndTab(edit->numberField(), 0.7);
        QCOMPARE(doc->undoStack()->count(), steps + 2);
        QCOMPARE(*doc->light(pendant).maintenance->value, 0.7);
        QVERIFY(near(maintenanceFactor(doc->scene(), doc->light(pendant)), 0.7));
        QVERIFY(near(maintenanceFactor(doc->scene(), doc->light(0)), 0.85));  // the others keep the scene's
        QCoreApplication::processEvents();  // laid out as shown
        QVERIFY(w.lightProperties()->grab().save("light_maintenance.png"));
        doc->undoStack()->undo();
        QVERIFY(doc->light(pendant).maintenance);
        QCOMPARE(edit->numberField()->value(), *doc->light(pendant).maintenance->value);
        doc->undoStack()->undo();
        QVERIFY(!doc->light(pendant).maintenance);
        QCOMPARE(edit->modeField()->currentIndex(), int(MaintenanceFactorEdit::kAbsent));
    }
};

QTEST_MAIN(TestProjectSettings)
#include "test_project_settings.moc"
