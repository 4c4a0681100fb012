// Daylight levels that follow the sun's altitude (issue 40; core/daylight/daylight_availability.h):
// the IES model against values worked out here from the published constants (not by calling the
// model twice), its shape (monotone in altitude, continuous, dark below civil twilight, no sun at
// or below the horizon, a low sun far dimmer than noon's), the CIE types' conditions; the scene
// file's "daylight_levels" key (parsed, written back, bad values refused in one line) and the
// bundled office resolved at 08:00, 12:00 and 18:55 with its levels following the sun.

#include "core/daylight/daylight.h"
#include "core/daylight/daylight_availability.h"
#include "core/daylight/sky_model.h"
#include "core/daylight/solar_position.h"
#include "core/scene/scene_io.h"

#include <QtTest>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

using namespace lucerna;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr SkyCondition kConditions[] = {SkyCondition::Clear, SkyCondition::PartlyCloudy, SkyCondition::Overcast};

// The published model, written out again for the checks: IES RP-21-1984 / IES Lighting Handbook.
double publishedSky(SkyCondition c, double altitudeDeg) {
    const double s = std::sin(altitudeDeg * kDeg);
    switch (c) {
    case SkyCondition::Clear: return 1000 * (0.8 + 15.5 * std::sqrt(s));
    case SkyCondition::PartlyCloudy: return 1000 * (0.3 + 45.0 * s);
    case SkyCondition::Overcast: return 1000 * (0.3 + 21.0 * s);
    }
    return -1;
}
double publishedAirMass(double h) { return 1 / (std::sin(h * kDeg) + 0.50572 * std::pow(h + 6.07995, -1.6364)); }
double publishedSun(SkyCondition c, double h) {
    if (c == SkyCondition::Overcast) return 0;
    return 127500 * std::exp(-(c == SkyCondition::Clear ? 0.21 : 0.80) * publishedAirMass(h));
}

// The global horizontal illuminance, lx: sky plus the sun's horizontal part.
double global(SkyCondition c, double h) {
    return skyHorizontalIlluminance(c, h) + sunDirectNormalIlluminance(c, h, std::nullopt) * std::max(0.0, std::sin(h * kDeg));
}

double altitudeDeg(const SolarPositionInput& in) { return 90.0 - solarPosition(in).zenithDeg; }

std::string readFile(const std::string& path) {
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

// The bundled office (Paris, a CIE clear sky, a sun of 70,000 lx at 11:00 on 21 March) with its
// levels following the sun: the sky's quantity and the sun's illuminance taken out.
std::string officeFollowing() {
    std::string json = readFile(LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json");
    const auto replace = [&](const std::string& from, const std::string& to) {
        const size_t at = json.find(from);
        if (at == std::string::npos) qFatal("office scene: %s not found", from.c_str());
        json.replace(at, from.size(), to);
    };
    replace("\"horizontal_illuminance\": 12000", "\"daylight_levels\": \"altitude\"");
    replace("\"illuminance\": 70000", "\"angular_diameter\": 0.53");
    return json;
}

Scene atTime(Scene s, const std::string& time) {
    for (Light& l : s.lights)
        if (l.type == LightType::Sun) l.sun->time = time;
    return s;
}

// The sky's and the sun's horizontal illuminance on an open plane, lx.
double eh(const Daylight& d) {
    return d.sky->horizontalIlluminance + (d.sun && d.sun->aboveHorizon ? d.sun->illuminanceLux * d.sun->towardSun.y : 0.0);
}

std::string rejection(const std::string& json) {
    try {
        parseScene(json, "/tmp/levels.json");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(accepted)";
}

}  // namespace

class TestDaylightLevels : public QObject {
    Q_OBJECT
private slots:
    void handComputedValues();
    void lowSunFarDimmerThanNoon();
    void monotoneContinuousAndDarkAtNight();
    void cieTypesToConditions();
    void sceneKeyParsesAndRoundTrips();
    void badValuesAreOneLineErrors();
    void officeThroughTheDay();
};

void TestDaylightLevels::handComputedValues() {
    // sin 30 deg = 1/2: the sky's formulas worked by hand. Clear: 0.8 + 15.5 / sqrt 2 klx.
    QVERIFY(std::abs(skyHorizontalIlluminance(SkyCondition::Clear, 30) - 11760.2) < 0.1);
    QVERIFY(std::abs(skyHorizontalIlluminance(SkyCondition::PartlyCloudy, 30) - 22800.0) < 1e-6);
    QVERIFY(std::abs(skyHorizontalIlluminance(SkyCondition::Overcast, 30) - 10800.0) < 1e-6);
    QVERIFY(std::abs(skyHorizontalIlluminance(SkyCondition::Clear, 90) - 16300.0) < 1e-6);
    // Kasten and Young's air mass: 1 at the zenith (less their 0.03% offset), 37.92 at the horizon.
    QVERIFY(std::abs(relativeOpticalAirMass(90) - 0.99971) < 1e-5);
    QVERIFY(std::abs(relativeOpticalAirMass(0) - 37.920) < 1e-3);
    QVERIFY(std::abs(relativeOpticalAirMass(30) - 1.99429) < 1e-5);
    // The sun at 30 deg, clear: 127.5 klx exp(-0.21 x 1.99429) = 83.874 klx; partly cloudy 25.860.
    QVERIFY(std::abs(sunDirectNormalIlluminance(SkyCondition::Clear, 30, std::nullopt) - 83873.9) < 0.5);
    QVERIFY(std::abs(sunDirectNormalIlluminance(SkyCondition::PartlyCloudy, 30, std::nullopt) - 25859.6) < 0.5);
    // The earth's orbit: 3.4% more on 2 January, about 3.4% less in early July.
    QVERIFY(std::abs(extraterrestrialIlluminance(2) - 127500 * 1.034) < 1e-6);
    QVERIFY(std::abs(extraterrestrialIlluminance(185) - 127500 * (1 + 0.034 * std::cos(2 * std::numbers::pi * 183 / 365))) < 1e-6);
    QCOMPARE(extraterrestrialIlluminance(std::nullopt), 127500.0);
    // Across altitudes, the formulas as published.
    for (const SkyCondition c : kConditions)
        for (const double h : {0.5, 1.0, 5.0, 12.5, 41.1, 60.0, 89.0}) {
            QVERIFY(std::abs(skyHorizontalIlluminance(c, h) - publishedSky(c, h)) < 1e-9 * publishedSky(c, h));
            QVERIFY(std::abs(sunDirectNormalIlluminance(c, h, std::nullopt) - publishedSun(c, h)) <= 1e-9 * publishedSun(c, h));
        }
}

void TestDaylightLevels::lowSunFarDimmerThanNoon() {
    // Paris, 21 March: the sun's highest altitude of the day (SPA, 5-minute steps) against 1 deg.
    SolarPositionInput in;
    in.latitudeDeg = 48.857;
    in.longitudeDeg = 2.352;
    in.utcOffsetHours = 1;
    double noon = -90;
    for (int minute = 9 * 60; minute <= 16 * 60; minute += 5) {
        in.time = LocalTime{2026, 3, 21, minute / 60, minute % 60, 0};
        noon = std::max(noon, altitudeDeg(in));
    }
    QVERIFY2(std::abs(noon - 41.5) < 0.5, qPrintable(QString::number(noon)));
    for (const SkyCondition c : kConditions) {
        // Sun and sky together: below a tenth of noon's for every sky.
        QVERIFY2(global(c, 1.0) < 0.1 * global(c, noon), qPrintable(QString::number(global(c, 1.0) / global(c, noon))));
        // The sky alone: below a tenth too, except the clear sky, whose published sqrt(sin h)
        // keeps 21% of noon's at 1 deg (a clear sky stays bright at sunset; the sun does not).
        const double ratio = skyHorizontalIlluminance(c, 1.0) / skyHorizontalIlluminance(c, noon);
        if (c == SkyCondition::Clear) QVERIFY2(ratio < 0.25, qPrintable(QString::number(ratio)));
        else QVERIFY2(ratio < 0.1, qPrintable(QString::number(ratio)));
    }
}

void TestDaylightLevels::monotoneContinuousAndDarkAtNight() {
    for (const SkyCondition c : kConditions) {
        double lastSky = -1, lastSun = -1;
        for (double h = -8; h <= 90; h += 0.125) {
            const double sky = skyHorizontalIlluminance(c, h), sun = sunDirectNormalIlluminance(c, h, 80);
            if (h > -6) QVERIFY2(sky > lastSky, qPrintable(QString("sky at %1").arg(h)));
            else QCOMPARE(sky, 0.0);
            QVERIFY2(sun >= lastSun, qPrintable(QString("sun at %1").arg(h)));
            if (h <= 0) QCOMPARE(sun, 0.0);  // at and below the horizon
            lastSky = sky;
            lastSun = sun;
        }
        // Continuous at the horizon (the clear sky's sqrt(sin h) is steep there: 0.002 lx at
        // 1e-12 degrees) and at civil twilight; half-way through the fade, half of A.
        QVERIFY(std::abs(skyHorizontalIlluminance(c, 1e-12) - skyHorizontalIlluminance(c, -1e-12)) < 0.01);
        QVERIFY(skyHorizontalIlluminance(c, -6 + 1e-9) < 1e-3);
        QCOMPARE(skyHorizontalIlluminance(c, -6), 0.0);
        QVERIFY(std::abs(skyHorizontalIlluminance(c, -3) - 0.5 * publishedSky(c, 0)) < 1e-9);
        // The sun's horizontal part goes to 0 with it.
        QVERIFY(sunDirectNormalIlluminance(c, 0.01, std::nullopt) * std::sin(0.01 * kDeg) < 0.01);
    }
    // An overcast sky hides the sun.
    QCOMPARE(sunDirectNormalIlluminance(SkyCondition::Overcast, 60, std::nullopt), 0.0);
}

void TestDaylightLevels::cieTypesToConditions() {
    Sky sky;
    sky.model = SkyModelType::CieGeneral;
    for (int t = 1; t <= 15; ++t) {
        sky.cieType = t;
        const SkyCondition expected = t <= 5 ? SkyCondition::Overcast : t <= 10 ? SkyCondition::PartlyCloudy : SkyCondition::Clear;
        QVERIFY2(skyCondition(sky) == expected, qPrintable(QString::number(t)));
    }
    sky.model = SkyModelType::CieOvercast;
    QVERIFY(skyCondition(sky) == SkyCondition::Overcast);
    sky.model = SkyModelType::Uniform;  // ISO 15469 type 5
    QVERIFY(skyCondition(sky) == SkyCondition::Overcast);
}

void TestDaylightLevels::sceneKeyParsesAndRoundTrips() {
    const Scene s = parseScene(officeFollowing(), LUCERNA_RESOURCE_DIR "/scenes/levels.json");
    QVERIFY(s.sky);
    QVERIFY(s.sky->levels == DaylightLevels::FollowAltitude);
    QVERIFY(!s.sky->horizontalIlluminance && !s.sky->zenithLuminance);
    const std::string text = saveSceneToString(s);
    QVERIFY2(text.find("\"daylight_levels\": \"altitude\"") != std::string::npos, text.c_str());
    QVERIFY(text.find("horizontal_illuminance") == std::string::npos);
    QCOMPARE(parseScene(text, LUCERNA_RESOURCE_DIR "/scenes/levels.json"), s);
    // "fixed" is today's reading: the numbers are needed and kept, and files without the key
    // read as before.
    std::string fixedJson = readFile(LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json");
    const Scene office = parseScene(fixedJson, LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json");
    QVERIFY(office.sky->levels == DaylightLevels::Fixed);
    fixedJson.replace(fixedJson.find("\"horizontal_illuminance\": 12000"), 31,
                      "\"horizontal_illuminance\": 12000, \"daylight_levels\": \"fixed\"");
    QCOMPARE(parseScene(fixedJson, LUCERNA_RESOURCE_DIR "/scenes/daylit_office.json"), office);
    QVERIFY(saveSceneToString(office).find("daylight_levels") == std::string::npos);
    // Fixed levels stay what the file says at any hour.
    const Daylight evening = resolveDaylight(atTime(office, "2026-03-21T18:55"));
    QCOMPARE(evening.sky->horizontalIlluminance, 12000.0);
    QCOMPARE(evening.sun->illuminanceLux, 70000.0);
    // The daylight factor's sky needs no quantity from the scene: it is a ratio.
    QVERIFY(std::abs(daylightFactorScene(s).skyHorizontalIlluminance - 10000) < 1e-6);
}

void TestDaylightLevels::badValuesAreOneLineErrors() {
    const std::string good = officeFollowing();
    const auto with = [&](const std::string& from, const std::string& to) {
        std::string json = good;
        json.replace(json.find(from), from.size(), to);
        return json;
    };
    const std::string levels = "\"daylight_levels\": \"altitude\"";
    struct Case {
        std::string json, says;
    } cases[] = {
        {with(levels, "\"daylight_levels\": \"sometimes\""), "sky.daylight_levels: expected \"altitude\" or \"fixed\""},
        {with(levels, "\"daylight_levels\": 1"), "sky.daylight_levels"},
        {with(levels, levels + ", \"horizontal_illuminance\": 12000"), "sky.horizontal_illuminance"},
        {with(levels, "\"daylight_levels\": \"fixed\""), "exactly one of zenith_luminance and horizontal_illuminance"},
        {with("\"angular_diameter\": 0.53", "\"illuminance\": 70000"), "has no \"illuminance\""},
    };
    for (const Case& c : cases) {
        const std::string message = rejection(c.json);
        QVERIFY2(message.find(c.says) != std::string::npos, message.c_str());
        QVERIFY2(message.find('\n') == std::string::npos, message.c_str());
    }
    // Without a sun there is nothing to follow; a perez sky has levels of its own.
    const std::string noSun = R"({"lucerna": 1, "camera": {"position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40,
"resolution": [16, 12]}, "materials": {}, "objects": [], "sky": {"model": "uniform", "daylight_levels": "altitude"}})";
    QVERIFY2(rejection(noSun).find("need a light of type \"sun\"") != std::string::npos, rejection(noSun).c_str());
    const std::string perez = R"({"lucerna": 1, "camera": {"position": [0, 1, 5], "target": [0, 1, 0], "fov_y": 40,
"resolution": [16, 12]}, "materials": {}, "objects": [], "site": {"latitude": 48.857, "longitude": 2.352, "utc_offset": 1},
"lights": [{"name": "sun", "type": "sun", "time": "2026-03-21T12:00"}],
"sky": {"model": "perez", "direct_normal_irradiance": 500, "diffuse_horizontal_irradiance": 100, "daylight_levels": "altitude"}})";
    QVERIFY2(rejection(perez).find("daylight_levels") != std::string::npos, rejection(perez).c_str());
}

void TestDaylightLevels::officeThroughTheDay() {
    const Scene office = parseScene(officeFollowing(), LUCERNA_RESOURCE_DIR "/scenes/levels.json");
    double ehAt[3] = {};
    const char* times[] = {"2026-03-21T08:00", "2026-03-21T12:00", "2026-03-21T18:55"};
    for (int k = 0; k < 3; ++k) {
        const Scene s = atTime(office, times[k]);
        const Daylight d = resolveDaylight(s);
        QVERIFY(d.sun && d.sky);
        // What resolveDaylight gives is the model at the sun's altitude and date (21 March: day 80).
        const double h = std::asin(d.sun->towardSun.y) / kDeg;
        QVERIFY(std::abs(d.sky->horizontalIlluminance - skyHorizontalIlluminance(SkyCondition::Clear, h)) < 1e-9 * (1 + d.sky->horizontalIlluminance));
        QCOMPARE(d.sun->illuminanceLux, sunDirectNormalIlluminance(SkyCondition::Clear, h, 80));
        // The sky's luminance gives that illuminance on an open plane (Lz x Eh / Lz).
        const double relativeEh = relativeHorizontalIlluminance(d.sky->sky, d.sky->towardSun);
        QVERIFY(std::abs(d.sky->zenithLuminance * relativeEh - d.sky->horizontalIlluminance) < 1e-6 * d.sky->horizontalIlluminance);
        ehAt[k] = eh(d);
    }
    QVERIFY2(ehAt[0] < ehAt[1] && ehAt[2] < ehAt[1],
             qPrintable(QString("%1 %2 %3").arg(ehAt[0]).arg(ehAt[1]).arg(ehAt[2])));
    QVERIFY2(ehAt[2] < 0.1 * ehAt[1], qPrintable(QString("%1 %2").arg(ehAt[2]).arg(ehAt[1])));
    // After sunset the ground and sky darken to nothing by civil twilight (about 19:35 in Paris).
    QCOMPARE(eh(resolveDaylight(atTime(office, "2026-03-21T20:30"))), 0.0);
}

QTEST_MAIN(TestDaylightLevels)
#include "test_daylight_levels.moc"
