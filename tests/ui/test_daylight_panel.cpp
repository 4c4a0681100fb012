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
// Issue 40: the levels follow the sun's altitude (the default for a sky added here; a file with
// numbers opens as Fixed), one undo step, the fields then showing what the model gives and the
// evening far dimmer than noon; a typed time sets the hour wherever the field was clicked; a
// listed city's coordinates show its name.

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
#include <QUndoStack>
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
    void levelsFollowTheSunThroughTheDay();
    void typedTimesSetTheHour();
    void listedCitiesShowTheirNames();
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

    // The sky: CIE overcast, its levels following the sun's altitude (new daylight's default: the
    // sun's illuminance key goes with it, in the same step); then fixed, where a typed 10,000 lx
    // holds; then given by its zenith luminance (the same sky: Eh / (7 pi / 9)), then a typed
    // zenith luminance.
    const int beforeSky = undo->count();
    choose(child<QComboBox>(panel, "daylightSkyModel"), "CIE overcast (traditional)");
    QVERIFY(doc.scene().sky);
    QCOMPARE(doc.scene().sky->model, SkyModelType::CieOvercast);
    QVERIFY(doc.scene().sky->levels == DaylightLevels::FollowAltitude);
    QVERIFY(!doc.scene().sky->horizontalIlluminance && !doc.scene().sky->zenithLuminance);
    QVERIFY(!sunOf(doc.scene()).sun->illuminanceGiven);
    QCOMPARE(undo->count(), beforeSky + 1);
    auto* levels = child<QComboBox>(panel, "daylightLevels");
    QCOMPARE(levels->currentIndex(), 0);
    QVERIFY(child<QDoubleSpinBox>(panel, "daylightSkyValue")->isReadOnly());
    choose(levels, "Fixed");
    QVERIFY(doc.scene().sky->levels == DaylightLevels::Fixed);
    QVERIFY(sunOf(doc.scene()).sun->illuminanceGiven);
    QVERIFY(!child<QDoubleSpinBox>(panel, "daylightSkyValue")->isReadOnly());
    typeInto(child<QDoubleSpinBox>(panel, "daylightSkyValue"), 10000);
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
    QVERIFY(!light.tiltField()->isVisibleTo(&light));  // a sun placed by time has no aim
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

namespace {

// The number of lux in "... 12,345 lx ..." after `word` in the dock's summary line.
double luxAfter(const QString& text, const QString& word) {
    const int at = text.indexOf(word);
    if (at < 0) return -1;
    QString digits;
    for (int k = at + int(word.size()); k < text.size() && text[k] != QLatin1Char('l'); ++k)
        if (text[k].isDigit()) digits += text[k];
    return double(digits.toLongLong());  // digits only: a whole number of lux
}

// Types `keys` into the time field as a designer would: focus elsewhere, a click into the field
// at `x` (pixels from its left), the keys, Enter.
void typeTime(QTimeEdit* time, QWidget* elsewhere, int x, const QString& keys) {
    elsewhere->setFocus(Qt::OtherFocusReason);
    auto* edit = time->findChild<QLineEdit*>();
    QTest::mouseClick(edit, Qt::LeftButton, {}, QPoint(x, edit->height() / 2));
    QCoreApplication::processEvents();  // the click's release selects the hour after Qt's handling
    QTest::keyClicks(time, keys);
    QTest::keyClick(time, Qt::Key_Return);
}

}  // namespace

// The bundled office (Paris, 21 March, a CIE clear sky of 12,000 lx and a sun of 70,000 lx) opens
// Fixed; Follow is one undo step; through the day the dock shows the model's levels, and at 18:55
// (the sun 1.2 degrees up) the open plane gets less than a tenth of noon's.
void TestDaylightPanel::levelsFollowTheSunThroughTheDay() {
    Document doc(loadScene(LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json"));
    QUndoStack* undo = doc.undoStack();
    const Scene opened = doc.scene();
    DaylightPanel panel(&doc);
    panel.resize(360, 900);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto* levels = child<QComboBox>(panel, "daylightLevels");
    auto* sunLux = child<QDoubleSpinBox>(panel, "daylightSunIlluminance");
    auto* skyValue = child<QDoubleSpinBox>(panel, "daylightSkyValue");
    auto* slider = child<QSlider>(panel, "daylightTimeSlider");
    auto* eh = child<QLabel>(panel, "daylightHorizontalIlluminance");
    QCOMPARE(levels->currentText(), QStringLiteral("Fixed"));
    QVERIFY(!sunLux->isReadOnly());
    // Fixed: 18:55 is as bright as 11:00 (what the designer saw).
    slider->setValue(18 * 60 + 55);
    QVERIFY2(luxAfter(eh->text(), "sky") == 12000, qPrintable(eh->text()));
    undo->undo();
    QCOMPARE(doc.scene(), opened);

    choose(levels, "Follow the sun's altitude (IES)");
    QCOMPARE(undo->count(), 1);  // one step for the sky and the sun's key
    QVERIFY(doc.scene().sky->levels == DaylightLevels::FollowAltitude);
    QVERIFY(!sunOf(doc.scene()).sun->illuminanceGiven);
    QVERIFY(sunLux->isReadOnly() && skyValue->isReadOnly());
    QVERIFY(!child<QComboBox>(panel, "daylightSkyQuantity")->isEnabled());

    // The fields and the summary show what resolveDaylight gives, hour by hour.
    const auto at = [&](int minutes) {
        slider->setValue(minutes);
        const Daylight d = resolveDaylight(doc.scene());
        if (std::abs(skyValue->value() - d.sky->horizontalIlluminance) > 0.5 || std::abs(sunLux->value() - d.sun->illuminanceLux) > 0.5 ||
            std::abs(luxAfter(eh->text(), "sky") - d.sky->horizontalIlluminance) > 0.5)
            qWarning("shown %g %g, %s; resolved %g %g", skyValue->value(), sunLux->value(), qPrintable(eh->text()),
                     d.sky->horizontalIlluminance, d.sun->illuminanceLux);
        return std::abs(skyValue->value() - d.sky->horizontalIlluminance) <= 0.5 && std::abs(sunLux->value() - d.sun->illuminanceLux) <= 0.5 &&
               std::abs(luxAfter(eh->text(), "sky") - d.sky->horizontalIlluminance) <= 0.5;
    };
    QVERIFY(at(8 * 60));
    const double morning = luxAfter(eh->text(), "Eh");
    QVERIFY(at(12 * 60));
    const double noon = luxAfter(eh->text(), "Eh"), noonSky = skyValue->value(), noonSun = sunLux->value();
    QVERIFY(at(18 * 60 + 55));
    const double evening = luxAfter(eh->text(), "Eh");
    QVERIFY2(morning < noon && evening < noon, qPrintable(QString("%1 %2 %3").arg(morning).arg(noon).arg(evening)));
    QVERIFY2(evening < 0.1 * noon, qPrintable(eh->text()));
    QVERIFY2(sunLux->value() < 0.01 * noonSun, qPrintable(eh->text()));
    // A clear sky alone keeps about a fifth of noon's at 1.2 degrees (the published sqrt(sin h));
    // a partly cloudy one (CIE type 9) drops below a tenth.
    QVERIFY2(skyValue->value() < 0.25 * noonSky, qPrintable(eh->text()));
    child<QSpinBox>(panel, "daylightCieType")->setValue(9);
    const double partlyCloudyEvening = skyValue->value();
    QVERIFY(at(12 * 60));
    QVERIFY2(partlyCloudyEvening < 0.1 * skyValue->value(),
             qPrintable(QString("%1 %2").arg(partlyCloudyEvening).arg(skyValue->value())));
    // The file keeps it; undo takes it all back, to Fixed and its numbers.
    QCOMPARE(parseScene(saveSceneToString(doc.scene()), "t.json"), doc.scene());
    undo->setIndex(0);
    QCOMPARE(doc.scene(), opened);
    QCOMPARE(levels->currentText(), QStringLiteral("Fixed"));
    QCOMPARE(skyValue->value(), 12000.0);
    QCOMPARE(sunLux->value(), 70000.0);
    QVERIFY(!skyValue->isReadOnly());
    // Fixed again from Follow keeps the light it gave at that moment, as numbers.
    undo->redo();
    slider->setValue(12 * 60);
    const Daylight followed = resolveDaylight(doc.scene());
    choose(levels, "Fixed");
    const Daylight fixed = resolveDaylight(doc.scene());
    QVERIFY(std::abs(fixed.sky->horizontalIlluminance - followed.sky->horizontalIlluminance) < 1e-6);
    QCOMPARE(fixed.sun->illuminanceLux, followed.sun->illuminanceLux);
    QVERIFY(sunOf(doc.scene()).sun->illuminanceGiven);
    // Following, removing the sun leaves the sky fixed at what it gave (nothing is left to
    // follow), in one step.
    choose(levels, "Follow the sun's altitude (IES)");
    choose(child<QComboBox>(panel, "daylightSkyModel"), "Uniform");
    const Scene beforeRemoval = doc.scene();
    const double skyNow = resolveDaylight(beforeRemoval).sky->horizontalIlluminance;
    const int stepsBefore = undo->count();
    clickBox(child<QCheckBox>(panel, "daylightSunPresent"));
    QCOMPARE(sunIndex(doc.scene()), -1);
    QVERIFY(doc.scene().sky->levels == DaylightLevels::Fixed);
    QVERIFY(std::abs(*doc.scene().sky->horizontalIlluminance - skyNow) < 1e-6);
    QCOMPARE(undo->count(), stepsBefore + 1);
    QCOMPARE(parseScene(saveSceneToString(doc.scene()), "t.json"), doc.scene());
    undo->undo();
    QCOMPARE(doc.scene(), beforeRemoval);
}

// The designer's case: a click into the field left a bare cursor, the typed hour was refused and
// only the minutes took the keys ("18:55" gave 12:55). Wherever the click lands, a typed time now
// starts at the hour; a whole selection too.
void TestDaylightPanel::typedTimesSetTheHour() {
    Document doc(loadScene(LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json"));
    DaylightPanel panel(&doc);
    panel.resize(360, 900);
    panel.show();
    QApplication::setActiveWindow(&panel);
    QVERIFY(QTest::qWaitForWindowActive(&panel));
    auto* time = child<QTimeEdit>(panel, "daylightTime");
    auto* date = child<QDateEdit>(panel, "daylightDate");
    auto* slider = child<QSlider>(panel, "daylightTimeSlider");
    auto* edit = time->findChild<QLineEdit*>();
    const int hourX = 6, minuteX = edit->fontMetrics().horizontalAdvance(QStringLiteral("12:0")) + 2;
    struct Case {
        int x;
        const char* keys;
        const char* time;
    } cases[] = {{hourX, "18:55", "18:55"}, {hourX, "8", "08:55"},  // the hour alone keeps the minutes
                 {minuteX, "08:00", "08:00"}, {minuteX, "18:55", "18:55"}, {hourX, "7:5", "07:05"}, {minuteX, "12", "12:05"}};
    for (const Case& c : cases) {
        typeTime(time, date, c.x, QString::fromLatin1(c.keys));
        const std::string expected = std::string("2026-03-21T") + c.time;
        QVERIFY2(*sunOf(doc.scene()).sun->time == expected,
                 qPrintable(QString("%1 typed at x %2: %3").arg(c.keys).arg(c.x).arg(QString::fromStdString(*sunOf(doc.scene()).sun->time))));
        QCOMPARE(slider->value(), QTime::fromString(QString::fromLatin1(c.time), "HH:mm").msecsSinceStartOfDay() / 60000);
    }
    // The whole text selected (Ctrl+A), then a time typed.
    date->setFocus(Qt::OtherFocusReason);
    time->setFocus(Qt::OtherFocusReason);
    QTest::keyClick(time, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(time, "16:40");
    QTest::keyClick(time, Qt::Key_Return);
    QCOMPARE(QString::fromStdString(*sunOf(doc.scene()).sun->time), QStringLiteral("2026-03-21T16:40"));
    // Once in the field, a click on the minutes edits the minutes.
    QTest::mouseClick(edit, Qt::LeftButton, {}, QPoint(minuteX, edit->height() / 2));
    QCoreApplication::processEvents();
    QTest::keyClicks(time, "05");
    QTest::keyClick(time, Qt::Key_Return);
    QCOMPARE(QString::fromStdString(*sunOf(doc.scene()).sun->time), QStringLiteral("2026-03-21T16:05"));
}

// A listed city's place shows its name, within 0.01 degrees (the bundled office's Paris is 48.857,
// 2.352; the list's 48.8566, 2.3522) and at its standard offset; anywhere else is a custom site.
void TestDaylightPanel::listedCitiesShowTheirNames() {
    Document doc(loadScene(LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json"));
    DaylightPanel panel(&doc);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    auto* city = child<QComboBox>(panel, "daylightCity");
    QCOMPARE(city->currentText(), QStringLiteral("Paris"));
    const auto siteAt = [&](double latitude, double longitude, double offset) {
        Site s = *doc.scene().site;
        s.latitudeDeg = latitude, s.longitudeDeg = longitude, s.utcOffsetHours = offset;
        doc.undoStack()->push(new EditSiteCommand(&doc, s, 0, "site"));
        return city->currentText();
    };
    QCOMPARE(siteAt(48.8566, 2.3522, 1), QStringLiteral("Paris"));
    QCOMPARE(siteAt(48.866, 2.343, 1), QStringLiteral("Paris"));        // 0.0094 and 0.0092 degrees away
    QCOMPARE(siteAt(48.87, 2.3522, 1), QStringLiteral("Custom site"));  // 0.0134 degrees north
    QCOMPARE(siteAt(48.857, 2.352, 2), QStringLiteral("Custom site"));  // summer time: another clock
    QCOMPARE(siteAt(19.08, 72.88, 5.5), QStringLiteral("Mumbai"));      // a fractional offset
    QCOMPARE(siteAt(-33.87, 151.21, 10), QStringLiteral("Sydney"));
    // Typed into the fields, as a designer would.
    typeInto(child<QDoubleSpinBox>(panel, "daylightUtcOffset"), 0);
    typeInto(child<QDoubleSpinBox>(panel, "daylightLatitude"), 51.507);
    typeInto(child<QDoubleSpinBox>(panel, "daylightLongitude"), -0.128);
    QCOMPARE(city->currentText(), QStringLiteral("London"));
}

QTEST_MAIN(TestDaylightPanel)
#include "test_daylight_panel.moc"
