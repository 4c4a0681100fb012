// The daylight panel (issue 22), clicked through as a designer would: a city places the site; the
// sun is added by its check box and placed by the panel's clock; a typed date and a drag of the
// time slider move it (the sun's `time` key and its direction change; a drag is one undo step, a
// key on the slider one each); the sky's model, CIE type, quantity (converted when switched) and
// ground reflectance; north as an angle; removing the sun under a CIE general sky is refused with
// a line saying why. Undo takes every edit back to the scene as opened, redo forward again, and
// the edited scene reads back equal from its file; a sun given by direction takes the clock.
// Through the window: the dock is in the View menu, Save then Open gives the same scene and the
// panel shows it, and the sun selected shows in the light panel without a place. A picture of
// the panel goes to the working directory.

#include "core/daylight/daylight.h"
#include "core/scene/scene_io.h"
#include "core/daylight/sky_model.h"
#include "ui/commands/daylight_commands.h"
#include "ui/scene_panels/daylight_panel.h"
#include "ui/properties/light_properties.h"
#include "ui/window/main_window.h"
#include "ui/scene_panels/outliner.h"
#include "ui/scene_panels/site_cities.h"
#include "window_test_helpers.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateEdit>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QSlider>
#include <QSpinBox>
#include <QStyleOptionSlider>
#include <QTemporaryDir>
#include <QTimeEdit>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <numbers>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// A 4 x 4 m floor, nothing else: the panel adds the daylight.
const char* const kFloorScene = R"({
  "lucerna": 1,
  "camera": {"position": [2, 1.6, 6], "target": [2, 1, 2], "up": [0, 1, 0], "fov_y": 50, "resolution": [64, 48]},
  "materials": {"floor": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "objects": [{"name": "floor", "material": "floor", "mesh": {"quad": [[0, 0, 0], [0, 0, 4], [4, 0, 4], [4, 0, 0]]}}]
}
)";

QString writeScene(const QTemporaryDir& dir, const char* name, const char* json) {
    const QString path = dir.filePath(name);
    std::ofstream(path.toStdString()) << json;
    return path;
}

// Chooses an item of a list as a user would (activated, not just the index).
void choose(QComboBox* combo, const QString& text) {
    const int i = combo->findText(text);
    QVERIFY2(i >= 0, qPrintable(text));
    combo->setCurrentIndex(i);
    emit combo->activated(i);
}

const Light& sunOf(const Scene& s) {
    const int i = sunIndex(s);
    if (i < 0) qFatal("no sun");
    return s.lights[size_t(i)];
}

double elevationDeg(const Scene& s) {
    return std::asin(sunDirection(s, sunOf(s)).y) * 180.0 / std::numbers::pi;
}

// Clicks the check box's indicator (a click right of its text misses it, as it would a user's).
void clickBox(QCheckBox* box) { QTest::mouseClick(box, Qt::LeftButton, {}, QPoint(6, box->height() / 2)); }

// Drags the slider's handle `dx` pixels in `steps` moves with the left button held.
void dragHandle(QSlider* slider, int dx, int steps) {
    QStyleOptionSlider opt;
    opt.initFrom(slider);
    opt.orientation = slider->orientation();
    opt.minimum = slider->minimum();
    opt.maximum = slider->maximum();
    opt.sliderPosition = slider->sliderPosition();
    opt.sliderValue = slider->value();
    opt.singleStep = slider->singleStep();
    opt.pageStep = slider->pageStep();
    opt.upsideDown = slider->invertedAppearance();
    opt.subControls = QStyle::SC_All;
    const QRect handle = slider->style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, slider);
    const QPointF start = handle.center();
    sendMouse(slider, QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
    for (int k = 1; k <= steps; ++k)
        sendMouse(slider, QEvent::MouseMove, start + QPointF(double(dx) * k / steps, 0), Qt::NoButton, Qt::LeftButton);
    sendMouse(slider, QEvent::MouseButtonRelease, start + QPointF(dx, 0), Qt::LeftButton, Qt::NoButton);
}

}  // namespace

class TestDaylightPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_daylight_panel"); }
    void editsEveryPartOfTheDaylight();
    void savedAndOpenedThroughTheWindow();
    void aSunByDirectionTakesTheClock();
};

void TestDaylightPanel::editsEveryPartOfTheDaylight() {
    QTemporaryDir dir;
    const Scene original = loadScene(writeScene(dir, "floor.json", kFloorScene).toStdString());
    Document doc(original);
    QUndoStack* undo = doc.undoStack();
    DaylightPanel panel(&doc);
    panel.resize(360, 800);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto* city = child<QComboBox>(panel, "daylightCity");
    auto* sunBox = child<QCheckBox>(panel, "daylightSunPresent");
    auto* date = child<QDateEdit>(panel, "daylightDate");
    auto* slider = child<QSlider>(panel, "daylightTimeSlider");
    auto* time = child<QTimeEdit>(panel, "daylightTime");
    auto* position = child<QLabel>(panel, "daylightSunPosition");
    auto* eh = child<QLabel>(panel, "daylightHorizontalIlluminance");
    auto* error = child<QLabel>(panel, "daylightError");

    // No site: the clock cannot place a sun yet.
    QCOMPARE(city->currentText(), QStringLiteral("No site"));
    QVERIFY(!slider->isEnabled());

    // A city places the site: its latitude, longitude and standard offset, north as it was.
    choose(city, "London");
    QVERIFY(doc.scene().site);
    QCOMPARE(doc.scene().site->latitudeDeg, 51.5074);
    QCOMPARE(doc.scene().site->longitudeDeg, -0.1278);
    QCOMPARE(doc.scene().site->utcOffsetHours, 0.0);
    QCOMPARE(doc.scene().site->north, V3d(0, 0, -1));
    QCOMPARE(child<QDoubleSpinBox>(panel, "daylightLatitude")->value(), 51.5074);
    QCOMPARE(undo->count(), 1);
    QVERIFY(slider->isEnabled());

    // The sun, placed by the panel's clock (21 June, noon, until changed).
    clickBox(sunBox);
    QCOMPARE(sunIndex(doc.scene()), 0);
    QCOMPARE(*sunOf(doc.scene()).sun->time, std::string("2025-06-21T12:00"));
    QCOMPARE(undo->count(), 2);
    // London, midsummer noon: the sun about 90 - 51.5 + 23.4 = 61.9 degrees up, in the south.
    QVERIFY2(std::abs(elevationDeg(doc.scene()) - 61.9) < 0.5, qPrintable(position->text()));
    QVERIFY2(position->text().contains("Elevation 6"), qPrintable(position->text()));
    QVERIFY2(eh->text().contains("sun"), qPrintable(eh->text()));

    // A typed date moves it: midwinter noon, about 90 - 51.5 - 23.4 = 15.1 degrees.
    date->setFocus();
    date->selectAll();
    QTest::keyClicks(date, "2025-12-21");
    QTest::keyClick(date, Qt::Key_Return);
    QCOMPARE(*sunOf(doc.scene()).sun->time, std::string("2025-12-21T12:00"));
    QVERIFY2(std::abs(elevationDeg(doc.scene()) - 15.1) < 0.5, qPrintable(position->text()));
    QCOMPARE(undo->count(), 3);

    // A drag of the time slider: later in the afternoon, the sun lower and further west; one step.
    const Scene beforeDrag = doc.scene();
    const V3d noon = sunDirection(beforeDrag, sunOf(beforeDrag));
    dragHandle(slider, 12, 4);
    const Light dragged = sunOf(doc.scene());  // a copy: undo replaces the scene
    QVERIFY2(*dragged.sun->time > std::string("2025-12-21T12:00"), dragged.sun->time->c_str());
    QCOMPARE(QString::fromStdString(dragged.sun->time->substr(11)), time->time().toString("HH:mm"));
    const V3d afternoon = sunDirection(doc.scene(), dragged);
    QVERIFY(afternoon.y < noon.y);
    QVERIFY(afternoon.x < noon.x);  // west is -x with north -z
    QCOMPARE(undo->count(), 4);
    undo->undo();
    QCOMPARE(doc.scene(), beforeDrag);
    undo->redo();
    QCOMPARE(doc.scene().lights[0], dragged);
    // Keys on the slider are a step each (5 minutes), as a click on its track would be.
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_Right);
    QTest::keyClick(slider, Qt::Key_Right);
    QCOMPARE(undo->count(), 6);
    QCOMPARE(slider->value(), (std::stoi(dragged.sun->time->substr(11, 2)) * 60 + std::stoi(dragged.sun->time->substr(14))) + 10);
    undo->undo();
    undo->undo();
    QCOMPARE(doc.scene().lights[0], dragged);

    // The sun's illuminance.
    typeInto(child<QDoubleSpinBox>(panel, "daylightSunIlluminance"), 90000);
    QCOMPARE(sunOf(doc.scene()).sun->illuminanceLux, 90000.0);

    // The sky: CIE overcast of 10,000 lx, then given by its zenith luminance (the same sky:
    // Eh / (7 pi / 9)), then a typed zenith luminance.
    choose(child<QComboBox>(panel, "daylightSkyModel"), "CIE overcast (traditional)");
    QVERIFY(doc.scene().sky);
    QCOMPARE(doc.scene().sky->model, SkyModelType::CieOvercast);
    QCOMPARE(*doc.scene().sky->horizontalIlluminance, 10000.0);
    choose(child<QComboBox>(panel, "daylightSkyQuantity"), "Lz (cd/m²)");
    QVERIFY(!doc.scene().sky->horizontalIlluminance);
    QVERIFY(std::abs(*doc.scene().sky->zenithLuminance - 10000 / (7 * std::numbers::pi / 9)) < 1e-6);
    QVERIFY(child<QDoubleSpinBox>(panel, "daylightSkyValue")->suffix().contains("cd"));
    typeInto(child<QDoubleSpinBox>(panel, "daylightSkyValue"), 3000);
    QCOMPARE(*doc.scene().sky->zenithLuminance, 3000.0);
    QVERIFY2(eh->text().contains("sky"), qPrintable(eh->text()));

    // A CIE general sky: the standard clear sky first, then type 8; the type's name is shown.
    choose(child<QComboBox>(panel, "daylightSkyModel"), "CIE general");
    QCOMPARE(doc.scene().sky->model, SkyModelType::CieGeneral);
    QCOMPARE(doc.scene().sky->cieType, 12);
    auto* cieType = child<QSpinBox>(panel, "daylightCieType");
    QVERIFY(cieType->isVisible());
    cieType->setFocus();
    cieType->selectAll();
    QTest::keyClicks(cieType, "8");
    QTest::keyClick(cieType, Qt::Key_Return);
    QCOMPARE(doc.scene().sky->cieType, 8);
    QVERIFY(child<QLabel>(panel, "daylightCieTypeName")->text().contains("corona"));

    // The ground.
    typeInto(child<QDoubleSpinBox>(panel, "daylightGroundReflectance"), 0.35);
    QCOMPARE(doc.scene().sky->groundReflectance, 0.35);

    // The sun cannot go while the sky is shaped by it: refused, said why, nothing changed.
    const int steps = undo->count();
    clickBox(sunBox);
    QCOMPARE(sunIndex(doc.scene()), 0);
    QVERIFY(sunBox->isChecked());
    QVERIFY(!error->text().isEmpty());
    QCOMPARE(undo->count(), steps);

    // North turned a quarter: north is +x, and the sun (placed by time) turns with it.
    const V3d before = sunDirection(doc.scene(), sunOf(doc.scene()));
    typeInto(child<QDoubleSpinBox>(panel, "daylightNorth"), 90);
    QCOMPARE(doc.scene().site->north, V3d(1, 0, 0));
    const V3d after = sunDirection(doc.scene(), sunOf(doc.scene()));
    QVERIFY(std::abs(after.y - before.y) < 1e-12);
    QVERIFY(std::abs(after.z - before.x) < 1e-9 && std::abs(after.x + before.z) < 1e-9);

    // Undo all the way: the scene as opened; redo all the way: as edited.
    const Scene edited = doc.scene();
    undo->setIndex(0);
    QCOMPARE(doc.scene(), original);
    QCOMPARE(city->currentText(), QStringLiteral("No site"));
    QVERIFY(!sunBox->isChecked());
    undo->setIndex(undo->count());
    QCOMPARE(doc.scene(), edited);
    // To look at: the panel at the width of the window's left dock.
    panel.resize(240, panel.sizeHint().height());
    QCoreApplication::processEvents();
    QVERIFY(panel.grab().save("daylight-panel.png"));

    // The file keeps it all.
    const std::string text = saveSceneToString(edited);
    QVERIFY2(text.find("\"time\": \"2025-12-21T") != std::string::npos, text.c_str());
    QCOMPARE(parseScene(text, dir.filePath("floor.json").toStdString()), edited);

    // No site: the sun keeps where it stands, by direction; one undo step brings the site back.
    const V3d standing = sunDirection(edited, sunOf(edited));
    choose(city, "No site");
    QVERIFY(!doc.scene().site);
    QVERIFY(!sunOf(doc.scene()).sun->time);
    QVERIFY((sunDirection(doc.scene(), sunOf(doc.scene())) - standing).length() < 1e-12);
    QCOMPARE(parseScene(saveSceneToString(doc.scene()), "t.json"), doc.scene());
    undo->undo();
    QCOMPARE(doc.scene(), edited);
}

void TestDaylightPanel::savedAndOpenedThroughTheWindow() {
    QTemporaryDir dir;
    MainWindow w(writeScene(dir, "floor.json", kFloorScene));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    // The dock is in the View menu, like the other panels.
    auto* dock = child<QDockWidget>(w, "daylightDock");
    bool listed = false;
    for (QAction* menu : w.menuBar()->actions())
        if (menu->menu() && menu->text().remove('&') == "View")
            listed = menu->menu()->actions().contains(dock->toggleViewAction());
    QVERIFY(listed);
    dock->raise();
    DaylightPanel& panel = *w.daylightPanel();

    choose(child<QComboBox>(panel, "daylightCity"), "Tokyo");
    clickBox(child<QCheckBox>(panel, "daylightSunPresent"));
    typeInto(child<QDoubleSpinBox>(panel, "daylightSunDiameter"), 0.6);
    choose(child<QComboBox>(panel, "daylightSkyModel"), "Uniform");
    typeInto(child<QDoubleSpinBox>(panel, "daylightGroundReflectance"), 0.1);
    const Scene edited = w.document()->scene();
    QCOMPARE(sunOf(edited).sun->angularDiameterDeg, 0.6);
    QCOMPARE(edited.sky->model, SkyModelType::Uniform);

    const QString path = dir.filePath("daylight.json");
    QVERIFY2(w.saveFileAs(path), qPrintable(w.lastError()));
    QVERIFY2(w.openFile(path), qPrintable(w.lastError()));
    QCOMPARE(w.document()->scene(), edited);
    QCOMPARE(child<QComboBox>(panel, "daylightCity")->currentText(), QStringLiteral("Tokyo"));
    QVERIFY(child<QCheckBox>(panel, "daylightSunPresent")->isChecked());
    QCOMPARE(child<QComboBox>(panel, "daylightSkyModel")->currentText(), QStringLiteral("Uniform"));
    QCOMPARE(child<QDoubleSpinBox>(panel, "daylightGroundReflectance")->value(), 0.1);

    // The sun selected in the outliner: the light panel shows its name and points to this panel;
    // it has no position, and its place is its time.
    w.outliner()->select(Outliner::Kind::Light, sunIndex(w.document()->scene()));
    LightProperties& light = *w.lightProperties();
    QVERIFY(child<QLabel>(light, "lightSunNote")->isVisibleTo(&light));
    QVERIFY(!light.positionFields()[0]->isVisibleTo(&light));
    QVERIFY(!light.directionFields()[0]->isVisibleTo(&light));
    QCOMPARE(light.nameField()->text(), QStringLiteral("sun"));
}

// A file's sun given by direction at a site stays so (the panel says how it is placed) until the
// clock is touched: then it is placed by time, its direction key gone (the file reads back equal).
void TestDaylightPanel::aSunByDirectionTakesTheClock() {
    QTemporaryDir dir;
    std::string json = kFloorScene;
    json.insert(json.rfind('}'), R"(,
  "lights": [{"name": "sun", "type": "sun", "illuminance": 60000, "direction": [0.3, -1, -0.2]}],
  "site": {"latitude": 40.4168, "longitude": -3.7038, "utc_offset": 1, "north": [0, 0, 1]})");
    Document doc(loadScene(writeScene(dir, "madrid.json", json.c_str()).toStdString()));
    DaylightPanel panel(&doc);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QCOMPARE(child<QComboBox>(panel, "daylightCity")->currentText(), QStringLiteral("Madrid"));
    QCOMPARE(child<QDoubleSpinBox>(panel, "daylightNorth")->value(), 180.0);
    QVERIFY(child<QLabel>(panel, "daylightSunPosition")->text().contains("by direction"));
    auto* time = child<QTimeEdit>(panel, "daylightTime");
    time->setFocus();
    time->setSelectedSection(QDateTimeEdit::HourSection);
    QTest::keyClicks(time, "09");
    time->setSelectedSection(QDateTimeEdit::MinuteSection);
    QTest::keyClicks(time, "30");
    QTest::keyClick(time, Qt::Key_Return);
    const Light sun = sunOf(doc.scene());
    QCOMPARE(QString::fromStdString(*sun.sun->time), QStringLiteral("2025-06-21T09:30"));
    QCOMPARE(sun.direction, Light().direction);
    QCOMPARE(child<QSlider>(panel, "daylightTimeSlider")->value(), 9 * 60 + 30);
    QVERIFY(!child<QLabel>(panel, "daylightSunPosition")->text().contains("by direction"));
    QCOMPARE(parseScene(saveSceneToString(doc.scene()), "t.json"), doc.scene());
    doc.undoStack()->undo();
    QCOMPARE(sunOf(doc.scene()).direction, V3d(0.3, -1, -0.2));
}

QTEST_MAIN(TestDaylightPanel)
#include "test_daylight_panel.moc"
