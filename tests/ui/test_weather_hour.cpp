// The daylight dock's Perez sky (issue 39; ui/scene_panels/weather_hour.h): on the bundled daylit
// office, with the bundled weather file, choosing "Perez" makes the clock's hour the scene's
// daylight in one undo step (the weather file's site, the sun where the clock says without an
// illuminance of its own, the row's irradiances); moving the clock to another hour takes that
// hour's irradiances; leaving it for the CIE overcast sky keeps the hour's light (the sun's Evn,
// the sky's Evd); the scene stays one the reader takes at every step.

#include "core/daylight/daylight.h"
#include "core/scene/scene_io.h"
#include "ui/commands/daylight_commands.h"
#include "ui/scene_panels/daylight_panel.h"
#include "window_test_helpers.h"

#include <QComboBox>
#include <QDateEdit>
#include <QLabel>
#include <QTimeEdit>
#include <QUndoStack>
#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {

const QString kWeather = LUCERNA_RESOURCE_DIR "/weather/paris_synthetic.epw";

void choose(QComboBox* combo, int i) {
    combo->setCurrentIndex(i);
    emit combo->activated(i);
}

// The scene as saved and read again: the reader's checks hold (a perez sky's sun has no
// illuminance, any other sun one).
void checkReadable(const Scene& s) {
    try {
        parseScene(saveSceneToString(s), "check.json");
    } catch (const SceneError& e) {
        QFAIL(e.what());
    }
}

}  // namespace

class TestWeatherHour : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { useTestSettings("test_weather_hour"); }

    void perezSkyFromTheClock() {
        Document doc(loadScene(LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json"));
        QUndoStack* undo = doc.undoStack();
        DaylightPanel panel(&doc);
        panel.resize(360, 900);
        panel.setWeatherQuestion([] { return kWeather; });
        auto* date = child<QDateEdit>(panel, "daylightDate");
        auto* time = child<QTimeEdit>(panel, "daylightTime");
        date->setDate(QDate(2021, 9, 20));
        time->setTime(QTime(12, 20));
        QCOMPARE(panel.localTime(), std::string("2021-09-20T12:20"));
        const int steps = undo->count();

        choose(child<QComboBox>(panel, "daylightSkyModel"), 4);  // Perez
        const Scene& s = doc.scene();
        QVERIFY(s.sky && s.sky->model == SkyModelType::Perez);
        QCOMPARE(s.sky->directNormalIrradiance, 771.0);  // the row of the hour ending 13:00 on 20 September
        QCOMPARE(s.sky->diffuseHorizontalIrradiance, 116.0);
        const Light& sun = s.lights[size_t(sunIndex(s))];
        QCOMPARE(*sun.sun->time, std::string("2021-09-20T12:20"));
        QVERIFY(!sun.sun->illuminanceGiven);
        QCOMPARE(s.site->latitudeDeg, 48.857);
        QCOMPARE(undo->count(), steps + 1);  // one step
        QVERIFY(child<QLabel>(panel, "daylightWeather")->text().contains("Paris (synthetic)"));
        checkReadable(s);
        const Daylight d = resolveDaylight(s);
        QVERIFY(d.sun && d.sun->illuminanceLux > 50000);  // a clear hour's beam
        panel.grab().save("daylight_perez.png");

        // Another hour of the same day: its irradiances.
        time->setTime(QTime(15, 10));
        QCOMPARE(doc.scene().sky->directNormalIrradiance, 683.0);  // the hour ending 16:00
        checkReadable(doc.scene());

        // Back to the CIE overcast sky: the hour's light stays.
        const Daylight before = resolveDaylight(doc.scene());
        choose(child<QComboBox>(panel, "daylightSkyModel"), 2);
        const Scene& after = doc.scene();
        QVERIFY(after.sky && after.sky->model == SkyModelType::CieOvercast);
        QVERIFY(std::abs(*after.sky->horizontalIlluminance - before.sky->horizontalIlluminance) < 1e-6);
        QCOMPARE(after.lights[size_t(sunIndex(after))].sun->illuminanceLux, before.sun->illuminanceLux);
        checkReadable(after);

        // Undo all the way: the original office.
        while (undo->count() > steps && undo->canUndo()) undo->undo();
        QVERIFY(doc.scene().sky->model == SkyModelType::CieGeneral);
        checkReadable(doc.scene());
    }
};

QTEST_MAIN(TestWeatherHour)
#include "test_weather_hour.moc"
