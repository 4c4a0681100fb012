// The annual calculation of SPEC.md section 6 (render/annual/annual_calculation.h): a closed form
// (an unobstructed horizontal plane gets Evd + Evn cos Z with the sun up, Evd without, every hour
// of a year) and the contract against `grid` on the hour's own scene (sceneOfHour) for an
// overcast and a clear hour in a side-lit room.

#include "core/daylight/daylight.h"
#include "core/daylight/perez_sky.h"
#include "core/daylight/solar_position.h"
#include "core/scene/scene_io.h"
#include "render/annual/annual_calculation.h"
#include "render/photometry/grid_calculation.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <thread>

#include <cmath>

using namespace lucerna;

namespace {

// A year of rows with varied weather: the beam on two days of three, a diffuse part that moves
// with the hour, the dew point with the season.
WeatherFile syntheticYear() {
    WeatherFile w;
    w.city = "Test";
    w.latitudeDeg = 47.05;
    w.longitudeDeg = 8.31;
    w.timeZoneHours = 1;
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    int dayIndex = 0;
    for (int m = 1; m <= 12; ++m)
        for (int d = 1; d <= kDays[m - 1]; ++d, ++dayIndex)
            for (int h = 1; h <= 24; ++h) {
                WeatherHour row;
                row.month = m, row.day = d, row.hour = h;
                const bool day = h >= 6 && h <= 20;
                row.directNormalIrradiance = day && dayIndex % 3 != 0 ? 150.0 + 40 * (h % 5) + 3 * (dayIndex % 17) : 0;
                row.diffuseHorizontalIrradiance = day ? 40.0 + 25 * (h % 7) + (dayIndex % 11) : 0;
                row.dewPointC = 4 + 8 * std::sin(3.14159 * dayIndex / 365.0);
                w.hours.push_back(row);
            }
    return w;
}

V3d sunAt(const WeatherFile& w, const WeatherHour& h) {
    SolarPositionInput in;
    in.time = LocalTime{w.year(), h.month, h.day, h.hour - 1, 30, 0};
    in.utcOffsetHours = w.timeZoneHours;
    in.latitudeDeg = w.latitudeDeg;
    in.longitudeDeg = w.longitudeDeg;
    return directionTowardSun(solarPosition(in), Site().north);
}

// A floor far below the points (which face up and see only the sky), and a side-lit room.
const char* kOpenPlane = R"({"lucerna": 1,
"camera": {"position": [0, 5, 10], "target": [0, 0, 0], "fov_y": 40, "resolution": [8, 8]},
"materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
"objects": [{"name": "floor", "material": "grey", "mesh": {"quad": [[-5, -3, -5], [-5, -3, 5], [5, -3, 5], [5, -3, -5]]}}]})";

// 4 x 3 m, 2.8 m high, a glazed opening in the south wall (+z), white-ish walls: the sun enters
// at noon and the sky's light is reflected around.
std::string sideLitRoom() {
    const auto quad = [](const char* name, const char* material, const char* q) {
        return std::string(R"({"name": ")") + name + R"(", "material": ")" + material + R"(", "mesh": {"quad": )" + q + "}}";
    };
    std::string objects = quad("floor", "floor", "[[0,0,0],[0,0,3],[4,0,3],[4,0,0]]") + "," +
                          quad("ceiling", "wall", "[[0,2.8,0],[4,2.8,0],[4,2.8,3],[0,2.8,3]]") + "," +
                          quad("north", "wall", "[[0,0,0],[4,0,0],[4,2.8,0],[0,2.8,0]]") + "," +
                          quad("west", "wall", "[[0,0,0],[0,2.8,0],[0,2.8,3],[0,0,3]]") + "," +
                          quad("east", "wall", "[[4,0,0],[4,0,3],[4,2.8,3],[4,2.8,0]]") + "," +
                          // The south wall around an opening from x 1 to 3, y 0.9 to 2.2.
                          quad("south_low", "wall", "[[0,0,3],[0,0.9,3],[4,0.9,3],[4,0,3]]") + "," +
                          quad("south_high", "wall", "[[0,2.2,3],[0,2.8,3],[4,2.8,3],[4,2.2,3]]") + "," +
                          quad("south_west", "wall", "[[0,0.9,3],[0,2.2,3],[1,2.2,3],[1,0.9,3]]") + "," +
                          quad("south_east", "wall", "[[3,0.9,3],[3,2.2,3],[4,2.2,3],[4,0.9,3]]") + "," +
                          quad("pane", "glass", "[[1,0.9,3],[1,2.2,3],[3,2.2,3],[3,0.9,3]]");
    return R"({"lucerna": 1,
"camera": {"position": [2, 1.5, 0.3], "target": [2, 1, 3], "fov_y": 60, "resolution": [8, 8]},
"materials": {"floor": {"type": "diffuse", "albedo": [0.35, 0.3, 0.25]}, "wall": {"type": "diffuse", "albedo": [0.7, 0.7, 0.65]},
              "glass": {"type": "glazing", "transmittance": [0.75, 0.75, 0.75]}},
"objects": [)" + objects + "]}";
}

}  // namespace

class TestAnnual : public QObject {
    Q_OBJECT
private slots:
    void openPlaneEveryHour();
    void sideLitRoomAgainstGrid();
    void resumesWithTheSameResult();
};

void TestAnnual::openPlaneEveryHour() {
    const Scene scene = parseScene(kOpenPlane, "open.json");
    const WeatherFile weather = syntheticYear();
    const std::vector<V3d> points = {V3d(0, 0, 0), V3d(1, 0, 0.5), V3d(-1, 0.2, -0.7)};
    AnnualSettings settings;
    settings.coefficients.paths = 4096;
    CancellationToken token;
    TaskContext ctx(token);
    const AnnualResult r = computeAnnual(scene, points, V3d(0, 1, 0), weather, settings, ctx);
    QCOMPARE(r.hours.size(), size_t(8760));
    int sunUp = 0;
    double worst = 0;
    for (size_t row = 0; row < r.hours.size(); ++row) {
        const WeatherHour& h = weather.hours[row];
        const V3d toward = sunAt(weather, h);
        const PerezSky sky({h.directNormalIrradiance, h.diffuseHorizontalIrradiance, h.dewPointC,
                            dayOfYear(2021, h.month, h.day), toward},
                           0);  // Evd and Evn need no integral
        QCOMPARE(r.hours[row].diffuseIlluminanceLux, sky.diffuseIlluminance());
        const bool up = toward.y > 0 && sky.directNormalIlluminance() > 0;
        sunUp += up;
        const double expected = sky.diffuseIlluminance() + (up ? sky.directNormalIlluminance() * toward.y : 0.0);
        for (size_t p = 0; p < points.size(); ++p) {
            const double e = r.lux[row * points.size() + p];
            if (expected == 0) {
                QCOMPARE(e, 0.0);
                continue;
            }
            worst = std::max(worst, std::abs(e / expected - 1));
            QVERIFY2(std::abs(e / expected - 1) < 0.005,
                     qPrintable(QString("row %1 point %2: %3 lx, expected %4").arg(row).arg(p).arg(e).arg(expected)));
            // With the sun up, the sun's disc straight onto the plane is its direct part (its
            // centre's cosine is not quite the disc's mean near the horizon).
            if (up) {
                const double direct = r.directSunLux[row * points.size() + p];
                QVERIFY(std::abs(direct - sky.directNormalIlluminance() * toward.y) < 0.005 * expected);
            }
        }
    }
    qInfo("%d hours with the sun up; worst relative error %.4f%%; tracing %.1f s, hours %.1f s", sunUp, 100 * worst,
          r.tracingSeconds, r.hoursSeconds);
    QVERIFY(sunUp > 2000);
}

void TestAnnual::sideLitRoomAgainstGrid() {
    const Scene scene = parseScene(sideLitRoom(), "room.json");
    const WeatherFile weather = syntheticYear();
    std::vector<V3d> points;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) points.emplace_back(0.8 + 1.2 * i, 0.85, 0.5 + 1.0 * k);
    AnnualSettings settings;
    settings.coefficients.paths = 32768;
    settings.coefficients.seed = 5;
    CancellationToken token;
    TaskContext ctx(token);
    const AnnualResult r = computeAnnual(scene, points, V3d(0, 1, 0), weather, settings, ctx);

    // An overcast hour (no beam: day index 93 of the year, a multiple of 3) and a clear one with
    // the sun through the opening (the next day).
    int outside = 0, values = 0;
    for (const auto& [month, day, hour] : {std::tuple{4, 4, 13}, std::tuple{4, 5, 13}}) {
        size_t row = 0;
        while (!(weather.hours[row].month == month && weather.hours[row].day == day && weather.hours[row].hour == hour)) ++row;
        const Scene hourScene = sceneOfHour(scene, weather, row);
        QVERIFY(hourScene.sky && hourScene.sky->model == SkyModelType::Perez);
        GridSettings grid;
        grid.targetRelativeError = 0.01;
        grid.timeLimitSeconds = 20;
        grid.seed = 9;
        const GridResult g = computeSceneGrid(std::make_shared<const Scene>(hourScene), points, V3d(0, 1, 0), grid, ctx);
        for (size_t p = 0; p < points.size(); ++p) {
            const double ea = r.lux[row * points.size() + p], ua = r.errorLux[row * points.size() + p];
            const double bar = std::sqrt(ua * ua + g.errorLux[p] * g.errorLux[p]);
            ++values;
            outside += std::abs(ea - g.lux[p]) > bar;
            qInfo("%02d-%02d-%02d point %zu: annual %.1f +- %.1f lx, grid %.1f +- %.1f lx, direct sun %.1f lx", month, day,
                  hour, p, ea, ua, g.lux[p], g.errorLux[p], double(r.directSunLux[row * points.size() + p]));
            QVERIFY2(std::abs(ea - g.lux[p]) < 3 * bar, "far outside the stated errors");
        }
    }
    // SPEC.md: at most 5% outside the bars, plus the binomial allowance (1.645 sigma).
    QVERIFY(outside <= 0.05 * values + 1.645 * std::sqrt(values * 0.05 * 0.95));
}

void TestAnnual::resumesWithTheSameResult() {
    // A year cancelled part-way keeps the points it traced; run again with resume it reads them
    // back, traces the rest, and gives the uninterrupted year's values bit for bit.
    const Scene scene = parseScene(sideLitRoom(), "room.json");
    const WeatherFile weather = syntheticYear();
    std::vector<V3d> points;
    for (int i = 0; i < 6; ++i)
        for (int k = 0; k < 5; ++k) points.emplace_back(0.4 + 0.6 * i, 0.85, 0.3 + 0.6 * k);
    AnnualSettings settings;
    settings.coefficients.paths = 2048;
    settings.coefficients.sunPaths = 64;
    settings.checkPoints = 4;
    const auto run = [&](const AnnualSettings& s, double cancelAt) {
        CancellationToken token;
        TaskContext ctx(token);
        std::atomic<bool> done{false};
        std::thread watcher([&] {
            while (!done && cancelAt < 1)
                if (ctx.progress() >= cancelAt) token.cancel();
                else std::this_thread::yield();
        });
        AnnualResult r = computeAnnual(scene, points, V3d(0, 1, 0), weather, s, ctx);
        done = true;
        watcher.join();
        return r;
    };
    const AnnualResult whole = run(settings, 2);
    QTemporaryDir dir;
    settings.checkpointDirectory = dir.path().toStdString();
    const AnnualResult cut = run(settings, 0.3);
    QVERIFY(cut.cancelled);
    QVERIFY(QFile::exists(QString::fromStdString(cut.checkpointPath)));
    settings.resume = true;
    const AnnualResult resumed = run(settings, 2);
    QVERIFY(!resumed.cancelled);
    qInfo("%zu of %zu points read back", resumed.resumedPoints, points.size());
    QVERIFY(resumed.resumedPoints > 0 && resumed.resumedPoints < points.size());
    QVERIFY(resumed.lux == whole.lux);
    QVERIFY(resumed.errorLux == whole.errorLux);
    QVERIFY(!QFile::exists(QString::fromStdString(resumed.checkpointPath)));  // done: it goes
}

QTEST_GUILESS_MAIN(TestAnnual)
#include "test_annual.moc"
