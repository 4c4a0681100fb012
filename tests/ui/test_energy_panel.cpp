// The Energy page (Edit > Energy...; README, "Energy (LENI; an addition)") and the circuit power
// of a light's properties, driven as a designer would: a building type chosen, factors typed and
// cleared, a light's circuit power typed; each change one undo step that undo takes back, the
// scene's "energy" key and "circuit_watts" as typed, W_L, W_P and LENI on the page as worked by
// hand; bad values refused with a line and no change.

#include "core/scene/scene_io.h"
#include "ui/properties/light_properties.h"
#include "ui/scene_panels/energy_panel.h"
#include "ui/scene_panels/outliner.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QDialog>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {

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

// Typed as a designer types, then Tab (Return would press the dialog's Close).
void typeAndTab(QLineEdit* field, const QString& text) {
    field->setFocus();
    QVERIFY(field->hasFocus());
    field->selectAll();
    if (text.isEmpty()) QTest::keyClick(field, Qt::Key_Delete);
    else QTest::keyClicks(field, text);
    QTest::keyClick(field, Qt::Key_Tab);
}

}  // namespace

class TestEnergyPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_energy_panel"); }
    void setThroughTheWindow();
};

void TestEnergyPanel::setThroughTheWindow() {
    QTemporaryDir dir;
    MainWindow w(writeScene(dir));
    w.resize(1400, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    Document* doc = w.document();
    QUndoStack* undo = doc->undoStack();
    QVERIFY(!doc->scene().energy);

    trigger(w, "actionEnergy");
    auto* dialog = child<QDialog>(w, "energyDialog");
    QVERIFY(QTest::qWaitForWindowExposed(dialog));
    dialog->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(dialog));
    auto* panel = dialog->findChild<EnergyPanel*>();
    QVERIFY(panel);
    QVERIFY(panel->leniLabel()->text().startsWith("LENI not computed: no building type"));
    QVERIFY(!panel->field(EnergyPanel::Factor::Occupancy)->isEnabled());

    // Offices, chosen with the keyboard: one step; the hours' defaults shown in the empty fields.
    int steps = undo->index();
    QComboBox* type = panel->buildingTypeField();
    type->setFocus();
    QTest::keyClick(type, Qt::Key_Down);
    QCOMPARE(undo->index(), steps + 1);
    QVERIFY(doc->scene().energy);
    QCOMPARE(doc->scene().energy->buildingType, BuildingType::Office);
    QCOMPARE(panel->field(EnergyPanel::Factor::DaytimeHours)->placeholderText(), QString("2250 (default for offices)"));
    QCOMPARE(panel->field(EnergyPanel::Factor::Area)->placeholderText(), QString("60.0 (the extent in plan)"));
    QCOMPARE(panel->leniLabel()->text(), QString("LENI not computed: 1 light states no power (give circuit_watts)"));

    // The bare light's circuit power, typed in its properties with the page closed (Close): one
    // step, written as typed.
    QTest::mouseClick(dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Close), Qt::LeftButton);
    QVERIFY(!dialog->isVisible());
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
    w.outliner()->select(Outliner::Kind::Light, 11);
    LightProperties* props = w.lightProperties();
    QCOMPARE(props->light(), 11);
    QVERIFY(props->circuitWattsField()->isVisibleTo(props));
    QCOMPARE(props->circuitWattsField()->placeholderText(), QString("not stated"));
    steps = undo->index();
    typeAndTab(props->circuitWattsField(), "30");
    QCOMPARE(undo->index(), steps + 1);
    QCOMPARE(doc->scene().lights[11].circuitWatts, std::optional<double>(30));
    QVERIFY(saveSceneToString(doc->scene()).find(R"("name": "bare", "type": "point", "position": [8.75, 2.8, 5], "lumens": 3000, "circuit_watts": 30})") !=
            std::string::npos);
    // Edit > Energy... again: the same page, up to date. By hand: W_L = 12 x 30 W x (2250 + 250) h / 1000 = 900 kWh/a, W_P = (5 + 1) x 60 = 360 kWh/a.
    const double defaultLeni = (12 * 30 * (2250 + 250) / 1000.0 + (5 + 1) * 60.0) / 60;
    trigger(w, "actionEnergy");
    QVERIFY(QTest::qWaitForWindowExposed(dialog));
    QCOMPARE(dialog->findChild<EnergyPanel*>(), panel);
    QCOMPARE(panel->lightingEnergyLabel()->text(), QString("W_L = 900.0 kWh/a"));
    QCOMPARE(panel->parasiticEnergyLabel()->text(), QString("W_P = 360.0 kWh/a (controls 300.0, emergency 60.0)"));
    QCOMPARE(panel->leniLabel()->text(), QString("LENI = %1 kWh/(m\u00b2\u00b7a) (A = 60.0 m\u00b2)").arg(defaultLeni, 0, 'f', 2));

    // An occupancy factor: one step; W_L = 360 W x (2250 x 0.8 + 250 x 0.8) h / 1000 = 720 kWh/a.
    dialog->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(dialog));
    steps = undo->index();
    typeAndTab(panel->field(EnergyPanel::Factor::Occupancy), "0.8");
    QCOMPARE(undo->index(), steps + 1);
    QCOMPARE(doc->scene().energy->occupancyFactor, std::optional<double>(0.8));
    QCOMPARE(panel->lightingEnergyLabel()->text(), QString("W_L = 720.0 kWh/a"));
    const double occupancyLeni = (360 * (2250 * 0.8 + 250 * 0.8) / 1000 + 360) / 60;
    QVERIFY(panel->leniLabel()->text().startsWith(QString("LENI = %1 ").arg(occupancyLeni, 0, 'f', 2)));
    // A given area: A = 48 m².
    typeAndTab(panel->field(EnergyPanel::Factor::Area), "48");
    QCOMPARE(undo->index(), steps + 2);
    QCOMPARE(doc->scene().energy->areaM2, std::optional<double>(48));
    QVERIFY(panel->leniLabel()->text().startsWith(QString("LENI = %1 ").arg((720 + 6 * 48.0) / 48, 0, 'f', 2)));
    QVERIFY(saveSceneToString(doc->scene()).find(R"("energy": {"building_type": "office", "occupancy_dependency_factor": 0.8, "area_m2": 48})") !=
            std::string::npos);

    // Refused: hours past a year, a factor over 1, a word. Nothing changes; the line says why.
    const Scene before = doc->scene();
    steps = undo->index();
    typeAndTab(panel->field(EnergyPanel::Factor::DaytimeHours), "8600");
    QVERIFY2(panel->messageLabel()->text().contains("more than the 8760 h of a year"), qPrintable(panel->messageLabel()->text()));
    QVERIFY(panel->field(EnergyPanel::Factor::DaytimeHours)->text().isEmpty());
    typeAndTab(panel->field(EnergyPanel::Factor::Daylight), "1.5");
    QVERIFY2(panel->messageLabel()->text().contains("Daylight dependency factor FD must be in [0, 1]"),
             qPrintable(panel->messageLabel()->text()));
    typeAndTab(panel->field(EnergyPanel::Factor::ConstantIlluminance), "abc");
    QVERIFY(panel->messageLabel()->text().contains("is not a number"));
    QCOMPARE(undo->index(), steps);
    QVERIFY(doc->scene() == before);

    // A field cleared: its default again, one step.
    typeAndTab(panel->field(EnergyPanel::Factor::Occupancy), QString());
    QCOMPARE(undo->index(), steps + 1);
    QVERIFY(!doc->scene().energy->occupancyFactor);
    QVERIFY(panel->messageLabel()->text().isEmpty());

    // Undo takes each step back, the page following.
    trigger(w, "actionUndo");
    QCOMPARE(doc->scene().energy->occupancyFactor, std::optional<double>(0.8));
    QCOMPARE(panel->field(EnergyPanel::Factor::Occupancy)->text(), QString("0.8"));
    trigger(w, "actionUndo");
    trigger(w, "actionUndo");
    QVERIFY(!doc->scene().energy->occupancyFactor && !doc->scene().energy->areaM2);
    QCOMPARE(panel->lightingEnergyLabel()->text(), QString("W_L = 900.0 kWh/a"));
    trigger(w, "actionUndo");
    QVERIFY(!doc->scene().lights[11].circuitWatts);
    QVERIFY(panel->leniLabel()->text().startsWith("LENI not computed: 1 light states no power"));
    trigger(w, "actionUndo");
    QVERIFY(!doc->scene().energy);
    QCOMPARE(type->currentIndex(), 0);
    trigger(w, "actionRedo");
    QCOMPARE(doc->scene().energy->buildingType, BuildingType::Office);

    // Hospitals, then "Not set": one step each.
    steps = undo->index();
    type->setCurrentIndex(3);
    emit type->activated(3);
    QCOMPARE(doc->scene().energy->buildingType, BuildingType::Hospital);
    QCOMPARE(panel->field(EnergyPanel::Factor::NightHours)->placeholderText(), QString("2000 (default for hospitals)"));
    type->setCurrentIndex(0);
    emit type->activated(0);
    QVERIFY(!doc->scene().energy);
    QCOMPARE(undo->index(), steps + 2);

    // Edit > Energy... again raises the same page.
    trigger(w, "actionEnergy");
    QCOMPARE(w.findChildren<EnergyPanel*>().size(), qsizetype(1));
    if (const QByteArray shots = qgetenv("LUCERNA_SCREENSHOTS"); !shots.isEmpty()) {
        trigger(w, "actionUndo");
        QCoreApplication::processEvents();
        QVERIFY(dialog->grab().save(QString::fromLocal8Bit(shots) + "/energy_dialog.png"));
    }
}

QTEST_MAIN(TestEnergyPanel)
#include "test_energy_panel.moc"
