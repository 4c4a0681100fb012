// The Energy tab of File > Project Settings (README, "Energy (LENI; an addition)") and the circuit
// power of a light's properties, driven as a designer would: Edit > Energy... opens the dialog on
// the tab; a building type chosen with the keyboard and factors typed change nothing until OK,
// which is one undo step with the other tabs' changes, and undo takes it back; Cancel changes
// nothing; W_L, W_P and LENI on the tab as worked by hand, following what is typed; bad values
// get a line saying why and keep the dialog open on OK. LUCERNA_SCREENSHOTS=DIR saves
// energy_tab.png and energy_tab_refused.png there.

#include "core/scene/scene_io.h"
#include "ui/properties/light_properties.h"
#include "ui/scene_panels/energy_settings_page.h"
#include "ui/scene_panels/outliner.h"
#include "ui/scene_panels/project_dialog.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <functional>

using namespace lucerna;
using namespace lucerna::test;

namespace {

using Factor = EnergySettingsPage::Factor;

// A 10 m x 6 m floor (60 m² in plan) under twelve point lights, eleven of 30 W and "bare", the
// last, stating no power.
QString writeScene(const QTemporaryDir& dir) {
    QString lights;
    for (int i = 0; i < 12; ++i)
        lights += QStringLiteral(R"(%1{"name": "%2", "type": "point", "position": [%3, 2.8, %4], "lumens": 3000%5})")
                      .arg(i ? ",\n    " : "")
                      .arg(i == 11 ? QStringLiteral("bare") : QStringLiteral("p%1").arg(i))
                      .arg(1.25 + 2.5 * (i % 4))
                      .arg(1 + 2 * (i / 4))
                      .arg(i == 11 ? QString() : QStringLiteral(R"(, "circuit_watts": 30)"));
    const QString scene = QStringLiteral(R"({"lucerna": 1,
  "camera": {"position": [5, 1.6, 5.5], "target": [5, 1, 0], "fov_y": 60, "resolution": [64, 48]},
  "materials": {"floor": {"type": "diffuse", "albedo": [0.3, 0.3, 0.3]}},
  "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[0, 0, 0], [0, 0, 6], [10, 0, 6], [10, 0, 0]]}}],
  "lights": [
    %1
  ]
})").arg(lights);
    const QString path = dir.filePath("office.json");
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(scene.toUtf8());
    return path;
}

// Typed as a designer types, then Tab (Return would press the dialog's OK).
void typeAndTab(QLineEdit* field, const QString& text) {
    field->setFocus();
    QVERIFY(field->hasFocus());
    field->selectAll();
    if (text.isEmpty()) QTest::keyClick(field, Qt::Key_Delete);
    else QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Tab);
}

void press(QDialog* dialog, QDialogButtonBox::StandardButton which) {
    QTest::mouseClick(dialog->findChild<QDialogButtonBox*>()->button(which), Qt::LeftButton);
}

EnergySettingsPage* energyPage(ProjectDialog* dialog) { return dialog->findChild<EnergySettingsPage*>("energyPage"); }

void saveShot(QWidget* w, const char* name) {
    const QByteArray dir = qgetenv("LUCERNA_SCREENSHOTS");
    if (dir.isEmpty()) return;
    QCoreApplication::processEvents();  // laid out as shown
    QVERIFY(w->grab().save(QString::fromLocal8Bit(dir) + "/" + name));
}

// How a dialog run by `through` ended.
enum class Ended { NotRun, Accepted, Rejected, LeftOpen };

// Triggers the window's action `name` and runs `fill` on the modal ProjectDialog it opens, active
// (a typed field counts when Tab takes the focus away). A dialog `fill` leaves open (a failed
// check in it, too) is cancelled, so that the test goes on to report.
Ended through(MainWindow& w, const char* name, const std::function<void(ProjectDialog*)>& fill) {
    Ended ended = Ended::NotRun;
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<ProjectDialog*>(QApplication::activeModalWidget());
        if (!dialog) return;
        dialog->activateWindow();
        // The platform's window is active before QApplication says so; focus follows the latter.
        if (!QTest::qWaitFor([dialog] { return QApplication::activeWindow() == dialog; })) return;
        fill(dialog);
        if (QTest::currentTestFailed()) ended = Ended::NotRun;
        else if (dialog->isVisible()) ended = Ended::LeftOpen;
        else ended = dialog->result() == QDialog::Accepted ? Ended::Accepted : Ended::Rejected;
        if (dialog->isVisible()) dialog->reject();
    });
    trigger(w, name);
    return ended;
}

}  // namespace

class TestEnergySettings : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_energy_settings"); }
    void setOnTheProjectSettingsTab();
    void badValuesKeepTheDialogOpen();
};

void TestEnergySettings::setOnTheProjectSettingsTab() {
    QTemporaryDir dir;
    MainWindow w(writeScene(dir));
    w.setSaveQuestion([] { return QMessageBox::Discard; });
    w.resize(1400, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    QUndoStack* undo = doc->undoStack();
    QVERIFY(!doc->scene().energy);
    const int opened = undo->count();

    // Edit > Energy... is Project Settings on its Energy tab. Offices chosen with the keyboard
    // and an occupancy factor typed: nothing changes before OK, which is one step.
    QCOMPARE(through(w, "actionEnergy", [&](ProjectDialog* dialog) {
        EnergySettingsPage* page = energyPage(dialog);
        QVERIFY(page);
        QCOMPARE(dialog->tabs()->currentWidget(), page);
        QCOMPARE(dialog->tabs()->tabText(dialog->tabs()->currentIndex()), QString("Energy"));
        QVERIFY(page->leniLabel()->text().startsWith("LENI not computed: no building type"));
        QVERIFY(!page->field(Factor::Occupancy)->isEnabled());
        QComboBox* type = page->buildingTypeField();
        type->setFocus();
        QTest::keyClick(type, Qt::Key_Down);
        QCOMPARE(type->currentIndex(), 1);
        QVERIFY(page->field(Factor::Occupancy)->isEnabled());
        QCOMPARE(page->field(Factor::DaytimeHours)->placeholderText(), QString("2250 (default for offices)"));
        QCOMPARE(page->field(Factor::Area)->placeholderText(), QString("60.0 (the extent in plan)"));
        QCOMPARE(page->leniLabel()->text(), QString("LENI not computed: 1 light states no power (give circuit_watts)"));
        typeAndTab(page->field(Factor::Occupancy), "0.8");
        QVERIFY(page->messageLabel()->text().isEmpty());
        QCOMPARE(undo->count(), opened);
        QVERIFY(!doc->scene().energy);
        press(dialog, QDialogButtonBox::Ok);
    }), Ended::Accepted);
    QCOMPARE(undo->count(), opened + 1);
    QCOMPARE(undo->undoText(), QString("Change project settings"));
    QVERIFY(doc->scene().energy);
    QCOMPARE(doc->scene().energy->buildingType, BuildingType::Office);
    QCOMPARE(doc->scene().energy->occupancyFactor, std::optional<double>(0.8));
    trigger(w, "actionUndo");
    QVERIFY(!doc->scene().energy);
    trigger(w, "actionRedo");
    QCOMPARE(doc->scene().energy->occupancyFactor, std::optional<double>(0.8));

    // The bare light's circuit power, typed in its properties: one step, written as typed.
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    w.outliner()->select(Outliner::Kind::Light, 11);
    LightProperties* props = w.lightProperties();
    QCOMPARE(props->light(), 11);
    QVERIFY(props->circuitWattsField()->isVisibleTo(props));
    QCOMPARE(props->circuitWattsField()->placeholderText(), QString("not stated"));
    int steps = undo->count();
    typeAndTab(props->circuitWattsField(), "30");
    QCOMPARE(undo->count(), steps + 1);
    QCOMPARE(doc->scene().lights[11].circuitWatts, std::optional<double>(30));
    QVERIFY(saveSceneToString(doc->scene()).find(R"("name": "bare", "type": "point", "position": [8.75, 2.8, 5], "lumens": 3000, "circuit_watts": 30})") !=
            std::string::npos);

    // File > Project Settings, the Energy tab clicked: the results by hand. W_L = 12 x 30 W x
    // (2250 + 250) h x 0.8 / 1000 = 720 kWh/a, W_P = (5 + 1) x 60 = 360 kWh/a. A given area and
    // the project's name on its tab, with OK: one step for both, the area's results shown first.
    steps = undo->count();
    QCOMPARE(through(w, "actionProjectSettings", [&](ProjectDialog* dialog) {
        QCOMPARE(dialog->tabs()->currentIndex(), 0);
        QTest::keyClicks(dialog->findChild<QLineEdit*>("projectName"), "Open-plan office");
        QTabBar* bar = dialog->tabs()->tabBar();
        QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(int(ProjectDialog::Tab::Energy)).center());
        EnergySettingsPage* page = energyPage(dialog);
        QCOMPARE(dialog->tabs()->currentWidget(), page);
        QCOMPARE(page->field(Factor::Occupancy)->text(), QString("0.8"));
        QCOMPARE(page->lightingEnergyLabel()->text(), QString("W_L = 720.0 kWh/a"));
        QCOMPARE(page->parasiticEnergyLabel()->text(), QString("W_P = 360.0 kWh/a (controls 300.0, emergency 60.0)"));
        QCOMPARE(page->leniLabel()->text(), QString("LENI = %1 kWh/(m\u00b2\u00b7a) (A = 60.0 m\u00b2)")
                                                .arg((720 + 360) / 60.0, 0, 'f', 2));
        typeAndTab(page->field(Factor::Area), "48");
        QCOMPARE(page->leniLabel()->text(), QString("LENI = %1 kWh/(m\u00b2\u00b7a) (A = 48.0 m\u00b2)")
                                                .arg((720 + 6 * 48.0) / 48, 0, 'f', 2));
        QCOMPARE(undo->count(), steps);
        saveShot(dialog, "energy_tab.png");
        press(dialog, QDialogButtonBox::Ok);
    }), Ended::Accepted);
    QCOMPARE(undo->count(), steps + 1);
    QCOMPARE(doc->scene().energy->areaM2, std::optional<double>(48));
    QCOMPARE(doc->scene().project->name, std::string("Open-plan office"));
    QVERIFY(saveSceneToString(doc->scene()).find(R"("energy": {"building_type": "office", "occupancy_dependency_factor": 0.8, "area_m2": 48})") !=
            std::string::npos);
    // Undo takes both back; redo sets both.
    trigger(w, "actionUndo");
    QVERIFY(!doc->scene().energy->areaM2 && !doc->scene().project);
    QCOMPARE(doc->scene().energy->occupancyFactor, std::optional<double>(0.8));
    trigger(w, "actionRedo");
    QCOMPARE(doc->scene().energy->areaM2, std::optional<double>(48));

    // Opened again and OK untouched: no step. Hospitals, a factor cleared and an emergency power,
    // then Cancel: nothing changes.
    const Scene before = doc->scene();
    steps = undo->count();
    QCOMPARE(through(w, "actionEnergy", [](ProjectDialog* dialog) { press(dialog, QDialogButtonBox::Ok); }),
             Ended::Accepted);
    QCOMPARE(undo->count(), steps);
    QCOMPARE(through(w, "actionEnergy", [&](ProjectDialog* dialog) {
        EnergySettingsPage* page = energyPage(dialog);
        QComboBox* type = page->buildingTypeField();
        type->setCurrentIndex(3);
        emit type->activated(3);
        QCOMPARE(page->field(Factor::NightHours)->placeholderText(), QString("2000 (default for hospitals)"));
        typeAndTab(page->field(Factor::Occupancy), QString());
        typeAndTab(page->field(Factor::EmergencyCharging), "1");
        QVERIFY(page->messageLabel()->text().isEmpty());
        press(dialog, QDialogButtonBox::Cancel);
    }), Ended::Rejected);
    QCOMPARE(undo->count(), steps);
    QVERIFY(doc->scene() == before);

    // "Not set": no `energy` key, one step; undo brings the settings back as they were.
    QCOMPARE(through(w, "actionEnergy", [&](ProjectDialog* dialog) {
        QComboBox* type = energyPage(dialog)->buildingTypeField();
        type->setCurrentIndex(0);
        emit type->activated(0);
        QVERIFY(!energyPage(dialog)->field(Factor::Area)->isEnabled());
        press(dialog, QDialogButtonBox::Ok);
    }), Ended::Accepted);
    QCOMPARE(undo->count(), steps + 1);
    QVERIFY(!doc->scene().energy);
    QVERIFY(saveSceneToString(doc->scene()).find("\"energy\"") == std::string::npos);
    trigger(w, "actionUndo");
    QVERIFY(doc->scene() == before);
}

void TestEnergySettings::badValuesKeepTheDialogOpen() {
    QTemporaryDir dir;
    MainWindow w(writeScene(dir));
    w.setSaveQuestion([] { return QMessageBox::Discard; });
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    const Scene before = doc->scene();
    const int steps = doc->undoStack()->count();

    // Hours past a year, a factor over 1, a word: the line says why as the field is left, the
    // field keeps what was typed, and neither OK nor Enter closes the dialog.
    QCOMPARE(through(w, "actionEnergy", [&](ProjectDialog* dialog) {
        EnergySettingsPage* page = energyPage(dialog);
        QComboBox* type = page->buildingTypeField();
        type->setCurrentIndex(1);
        emit type->activated(1);
        QLabel* message = page->messageLabel();
        typeAndTab(page->field(Factor::DaytimeHours), "8600");
        QVERIFY2(message->text().contains("more than the 8760 h of a year"), qPrintable(message->text()));
        QCOMPARE(page->field(Factor::DaytimeHours)->text(), QString("8600"));
        dialog->tabs()->setCurrentIndex(0);
        press(dialog, QDialogButtonBox::Ok);
        QVERIFY(dialog->isVisible());
        QCOMPARE(dialog->tabs()->currentWidget(), page);
        typeAndTab(page->field(Factor::DaytimeHours), QString());
        QVERIFY(message->text().isEmpty());

        QLineEdit* daylight = page->field(Factor::Daylight);
        daylight->setFocus();
        QTest::keyClicks(daylight, "1.5");
        QTest::keyClick(daylight, Qt::Key_Return);
        QVERIFY(dialog->isVisible());
        QVERIFY2(message->text() == "Daylight dependency factor FD must be in [0, 1]", qPrintable(message->text()));
        QVERIFY(daylight->hasFocus());
        typeAndTab(page->field(Factor::ConstantIlluminance), "abc");
        QVERIFY2(message->text() == "Constant illuminance factor Fc: \"abc\" is not a number", qPrintable(message->text()));
        typeAndTab(page->field(Factor::Area), "0");
        saveShot(dialog, "energy_tab_refused.png");
        press(dialog, QDialogButtonBox::Ok);
        QVERIFY(dialog->isVisible());
        QVERIFY(page->field(Factor::ConstantIlluminance)->hasFocus());
        typeAndTab(page->field(Factor::ConstantIlluminance), QString());
        QVERIFY2(message->text().contains("Daylight dependency factor FD"), qPrintable(message->text()));
        typeAndTab(daylight, QString());
        QVERIFY2(message->text() == QString("Floor area A must be in (0, 1e+09] m\u00b2"), qPrintable(message->text()));
        typeAndTab(page->field(Factor::Area), QString());
        QVERIFY(message->text().isEmpty());
        press(dialog, QDialogButtonBox::Cancel);
    }), Ended::Rejected);
    QCOMPARE(doc->undoStack()->count(), steps);
    QVERIFY(doc->scene() == before);
}

QTEST_MAIN(TestEnergySettings)
#include "test_energy_settings.moc"
