// The climate-based daylight metrics (SPEC.md section 6, core/daylight/annual_metrics.h) on
// constructed hourly matrices whose figures are known by hand: occupied hours, DA300 and UDI with
// their band edges, sDA300/50% and ASE1000,250h with their strict and inclusive limits, points left
// out of the plane, EN 17037's daylight hours and levels.

#include "core/daylight/annual_metrics.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

using namespace lucerna;

namespace {

constexpr double kTolerance = 1e-12;

#define QVERIFY_NEAR(actual, expected)                                                                        \
    QVERIFY2(std::abs(double(actual) - double(expected)) < kTolerance,                                        \
             qPrintable(QStringLiteral("%1 = %2, expected %3").arg(QString::fromLatin1(#actual)).arg(double(actual), 0, 'g', 17) \
                            .arg(double(expected), 0, 'g', 17)))

// The rows of an EPW year: 1 January hour 1 to 31 December hour 24, with 29 February in a leap
// year (8784 rows) and without it otherwise (8760).
std::vector<AnnualHour> calendarYear(bool leap = false) {
    const std::array<int, 12> monthDays{31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    std::vector<AnnualHour> rows;
    for (int month = 1; month <= 12; ++month)
        for (int day = 1; day <= monthDays[size_t(month - 1)]; ++day)
            for (int hour = 1; hour <= 24; ++hour) rows.push_back({month, day, hour, 0.0});
    return rows;
}

// SPEC.md's default office day as EPW rows: the hours ending at 09:00 to 18:00 (instants 08:30 to
// 17:30), ten a day.
bool defaultOccupied(const AnnualHour& h) { return h.hour >= 9 && h.hour <= 18; }

// An hours x points matrix, row-major as computeAnnualMetrics takes it.
struct Matrix {
    size_t points;
    std::vector<float> values;
    Matrix(size_t hours, size_t pointCount, float fill) : points(pointCount), values(hours * pointCount, fill) {}
    float& at(size_t hour, size_t point) { return values[hour * points + point]; }
};

// DA300 and UDI patterns over the default occupied hours, k counting them from the year's first:
//  0: 400 lx in the first 60% of them (k < 2190), 50 lx after;
//  1: 5000 lx throughout;
//  2: the band edges in turn, k % 10 picking 0, 99, 100, 101, 299, 300, 301, 2999, 3000, 3001 lx;
//  3: 300 lx for k < 1824 (one hour short of half), 0 lx after.
// Unoccupied hours are at 100,000 lx, so that any of them taken for occupied shows.
Matrix bandPatterns(const std::vector<AnnualHour>& year) {
    constexpr std::array<float, 10> kEdges{0, 99, 100, 101, 299, 300, 301, 2999, 3000, 3001};
    Matrix m(year.size(), 4, 100000.0f);
    size_t k = 0;
    for (size_t h = 0; h < year.size(); ++h) {
        if (!defaultOccupied(year[h])) continue;
        m.at(h, 0) = k < 2190 ? 400.0f : 50.0f;
        m.at(h, 1) = 5000.0f;
        m.at(h, 2) = kEdges[k % 10];
        m.at(h, 3) = k < 1824 ? 300.0f : 0.0f;
        ++k;
    }
    return m;
}

}  // namespace

class TestAnnualMetrics : public QObject {
    Q_OBJECT
private slots:
    void occupiedHoursOfTheYear();
    void pointFiguresFromDesignedPatterns();
    void widerOccupancyTakesInMoreHours();
    void sdaAndUdiOverThePlane();
    void countedLeavesPointsOutOfThePlane();
    void aseNeedsMoreThan250Hours();
    void noOccupiedHoursGivesZeros();
    void daylightHoursRankByEvdThenRow();
    void en17037LevelsFromConstructedHours();
    void mismatchedSizesThrow();
    void fullYearOfAThousandPoints();
};

void TestAnnualMetrics::occupiedHoursOfTheYear() {
    const std::vector<AnnualHour> year = calendarYear();
    QCOMPARE(year.size(), size_t(8760));
    auto count = [&](const Occupancy& o, const std::vector<AnnualHour>& rows) {
        int n = 0;
        for (const AnnualHour& h : rows) n += o.contains(h);
        return n;
    };
    QCOMPARE(count(Occupancy{}, year), 3650);
    QCOMPARE(count(Occupancy{7, 19}, year), 4380);
    QCOMPARE(count(Occupancy{0, 24}, year), 8760);
    QCOMPARE(count(Occupancy{}, calendarYear(true)), 3660);
    // The row ending at 09:00 stands for 08:30, inside [08:00, 18:00); the one ending at 19:00
    // for 18:30, outside.
    const Occupancy office;
    QVERIFY(!office.contains({1, 1, 8}));
    QVERIFY(office.contains({1, 1, 9}));
    QVERIFY(office.contains({1, 1, 18}));
    QVERIFY(!office.contains({1, 1, 19}));
    QVERIFY(!office.contains({1, 1, 24}));
    QVERIFY(Occupancy({7, 19}).contains({1, 1, 8}));
    QVERIFY(Occupancy({7, 19}).contains({1, 1, 19}));
    QVERIFY(!Occupancy({7, 19}).contains({1, 1, 20}));
    // Bounds on the half hour: the start is in, the end is out.
    QVERIFY(Occupancy({8.5, 17.5}).contains({1, 1, 9}));
    QVERIFY(!Occupancy({8.5, 17.5}).contains({1, 1, 18}));
    QCOMPARE(count(Occupancy{8.5, 17.5}, year), 3285);
}

void TestAnnualMetrics::pointFiguresFromDesignedPatterns() {
    const std::vector<AnnualHour> year = calendarYear();
    const Matrix lux = bandPatterns(year);
    const AnnualMetrics m = computeAnnualMetrics(year, 4, lux.values, {}, Occupancy{});
    QCOMPARE(m.occupiedHours, 3650);
    QCOMPARE(m.points.size(), size_t(4));

    const PointAnnualMetrics& p0 = m.points[0];
    QVERIFY_NEAR(p0.da300, 0.6);
    QVERIFY_NEAR(p0.udiFellShort, 0.4);
    QVERIFY_NEAR(p0.udiUseful, 0.6);
    QVERIFY_NEAR(p0.udiExceeded, 0.0);
    QVERIFY_NEAR(p0.meanLux, (2190 * 400.0 + 1460 * 50.0) / 3650);  // 260

    const PointAnnualMetrics& p1 = m.points[1];
    QVERIFY_NEAR(p1.da300, 1.0);
    QVERIFY_NEAR(p1.udiFellShort, 0.0);
    QVERIFY_NEAR(p1.udiUseful, 0.0);
    QVERIFY_NEAR(p1.udiExceeded, 1.0);
    QVERIFY_NEAR(p1.meanLux, 5000.0);

    // 0 and 99 fall short; 100 to 3000 inclusive are useful; 3001 exceeds; 300 and up reach DA.
    const PointAnnualMetrics& p2 = m.points[2];
    QVERIFY_NEAR(p2.da300, 0.5);
    QVERIFY_NEAR(p2.udiFellShort, 0.2);
    QVERIFY_NEAR(p2.udiUseful, 0.7);
    QVERIFY_NEAR(p2.udiExceeded, 0.1);
    QVERIFY_NEAR(p2.meanLux, (0 + 99 + 100 + 101 + 299 + 300 + 301 + 2999 + 3000 + 3001) / 10.0);  // 1020

    const PointAnnualMetrics& p3 = m.points[3];
    QVERIFY_NEAR(p3.da300, 1824.0 / 3650);
    QVERIFY_NEAR(p3.udiFellShort, 1826.0 / 3650);
    QVERIFY_NEAR(p3.udiUseful, 1824.0 / 3650);
    QVERIFY_NEAR(p3.meanLux, 1824 * 300.0 / 3650);

    for (const PointAnnualMetrics& p : m.points) QCOMPARE(p.aseHours, 0);  // no direct-sun matrix
}

void TestAnnualMetrics::widerOccupancyTakesInMoreHours() {
    // 7-19 adds the rows ending at 08:00 and 19:00, at 100,000 lx in the patterns: 730 more hours
    // above 300 and above 3000 lx at every point.
    const std::vector<AnnualHour> year = calendarYear();
    const Matrix lux = bandPatterns(year);
    const AnnualMetrics m = computeAnnualMetrics(year, 4, lux.values, {}, Occupancy{7, 19});
    QCOMPARE(m.occupiedHours, 4380);
    QVERIFY_NEAR(m.points[0].da300, (2190.0 + 730) / 4380);
    QVERIFY_NEAR(m.points[0].udiFellShort, 1460.0 / 4380);
    QVERIFY_NEAR(m.points[0].udiUseful, 2190.0 / 4380);
    QVERIFY_NEAR(m.points[0].udiExceeded, 730.0 / 4380);
    QVERIFY_NEAR(m.points[0].meanLux, (2190 * 400.0 + 1460 * 50.0 + 730 * 100000.0) / 4380);
    QVERIFY_NEAR(m.points[1].udiExceeded, 1.0);
}

void TestAnnualMetrics::sdaAndUdiOverThePlane() {
    const std::vector<AnnualHour> year = calendarYear();
    const Matrix lux = bandPatterns(year);
    const AnnualMetrics m = computeAnnualMetrics(year, 4, lux.values, {}, Occupancy{});
    QCOMPARE(m.countedPoints, 4);
    // DA300 0.6, 1, exactly 0.5 (counts) and 1824/3650 (does not): three points of four.
    QVERIFY_NEAR(m.sda300, 75.0);
    QVERIFY_NEAR(m.udiFellShort, (0.4 + 0.0 + 0.2 + 1826.0 / 3650) / 4);
    QVERIFY_NEAR(m.udiUseful, (0.6 + 0.0 + 0.7 + 1824.0 / 3650) / 4);
    QVERIFY_NEAR(m.udiExceeded, (0.0 + 1.0 + 0.1 + 0.0) / 4);
    QVERIFY_NEAR(m.udiFellShort + m.udiUseful + m.udiExceeded, 1.0);
    QVERIFY_NEAR(m.ase, 0.0);
}

void TestAnnualMetrics::countedLeavesPointsOutOfThePlane() {
    const std::vector<AnnualHour> year = calendarYear();
    const Matrix lux = bandPatterns(year);
    const std::vector<uint8_t> counted{1, 0, 1, 0};  // points 1 and 3 inside geometry
    const AnnualMetrics m = computeAnnualMetrics(year, 4, lux.values, {}, Occupancy{}, counted);
    QCOMPARE(m.countedPoints, 2);
    QVERIFY_NEAR(m.sda300, 100.0);
    QVERIFY_NEAR(m.udiFellShort, (0.4 + 0.2) / 2);
    QVERIFY_NEAR(m.udiUseful, (0.6 + 0.7) / 2);
    QVERIFY_NEAR(m.udiExceeded, (0.0 + 0.1) / 2);
    // Left out of the plane, not out of the per-point figures.
    QVERIFY_NEAR(m.points[1].udiExceeded, 1.0);
    QVERIFY_NEAR(m.points[3].da300, 1824.0 / 3650);

    // With no point counted the plane has no figures.
    const AnnualMetrics none = computeAnnualMetrics(year, 4, lux.values, {}, Occupancy{}, std::vector<uint8_t>(4, 0));
    QCOMPARE(none.countedPoints, 0);
    QVERIFY_NEAR(none.sda300, 0.0);
    QVERIFY_NEAR(none.udiUseful, 0.0);
    for (const En17037Level& level : none.en17037) QVERIFY(!level.met);
    QVERIFY_NEAR(none.points[0].da300, 0.6);
}

void TestAnnualMetrics::aseNeedsMoreThan250Hours() {
    // Direct sun, k counting the default occupied hours:
    //  0: 1001 lx in the first 251 (more than 250: counts);
    //  1: 1001 lx in the first 250 (not more than 250);
    //  2: exactly 1000 lx in every hour (not more than 1000 lx: no hour);
    //  3: 5000 lx in every unoccupied hour, 1001 lx in the first 251 occupied ones.
    const std::vector<AnnualHour> year = calendarYear();
    const Matrix lux(year.size(), 4, 0.0f);
    Matrix sun(year.size(), 4, 0.0f);
    size_t k = 0;
    for (size_t h = 0; h < year.size(); ++h) {
        sun.at(h, 2) = 1000.0f;
        if (!defaultOccupied(year[h])) {
            sun.at(h, 3) = 5000.0f;
            continue;
        }
        sun.at(h, 0) = k < 251 ? 1001.0f : 0.0f;
        sun.at(h, 1) = k < 250 ? 1001.0f : 0.0f;
        sun.at(h, 3) = k < 251 ? 1001.0f : 0.0f;
        ++k;
    }
    const AnnualMetrics m = computeAnnualMetrics(year, 4, lux.values, sun.values, Occupancy{});
    QCOMPARE(m.points[0].aseHours, 251);
    QCOMPARE(m.points[1].aseHours, 250);
    QCOMPARE(m.points[2].aseHours, 0);
    QCOMPARE(m.points[3].aseHours, 251);
    QVERIFY_NEAR(m.ase, 50.0);

    const std::vector<uint8_t> counted{1, 1, 1, 0};
    const AnnualMetrics left = computeAnnualMetrics(year, 4, lux.values, sun.values, Occupancy{}, counted);
    QVERIFY_NEAR(left.ase, 100.0 / 3);
    QCOMPARE(left.points[3].aseHours, 251);

    // The direct-sun illuminance alone decides, not the total.
    QVERIFY_NEAR(m.sda300, 0.0);
}

void TestAnnualMetrics::noOccupiedHoursGivesZeros() {
    const std::vector<AnnualHour> year = calendarYear();
    const Matrix lux(year.size(), 2, 5000.0f);
    const Matrix sun(year.size(), 2, 5000.0f);
    const AnnualMetrics m = computeAnnualMetrics(year, 2, lux.values, sun.values, Occupancy{20, 20});
    QCOMPARE(m.occupiedHours, 0);
    for (const PointAnnualMetrics& p : m.points) {
        QVERIFY_NEAR(p.da300, 0.0);
        QVERIFY_NEAR(p.udiFellShort, 0.0);
        QVERIFY_NEAR(p.udiUseful, 0.0);
        QVERIFY_NEAR(p.udiExceeded, 0.0);
        QVERIFY_NEAR(p.meanLux, 0.0);
        QCOMPARE(p.aseHours, 0);
    }
    QVERIFY_NEAR(m.sda300, 0.0);
    QVERIFY_NEAR(m.ase, 0.0);
    QVERIFY_NEAR(m.udiExceeded, 0.0);
}

void TestAnnualMetrics::daylightHoursRankByEvdThenRow() {
    std::vector<AnnualHour> rows = calendarYear();
    rows.resize(10);
    const std::array<double, 10> evd{5, 7, 7, 0, 7, 3, 9, 5, 0, 1};
    for (size_t i = 0; i < rows.size(); ++i) rows[i].diffuseIlluminanceLux = evd[i];
    // Ranked: 6 (9 lx), 1, 2, 4 (7 lx), then 0 and 7 tie at 5 lx for the fifth place: 0 is earlier.
    QCOMPARE(en17037DaylightHours(rows), (std::vector<size_t>{0, 1, 2, 4, 6}));

    // An eleventh row at 7 lx ranks above both 5s; the half of 11 rows is 5.
    rows.push_back({1, 1, 11, 7});
    QCOMPARE(en17037DaylightHours(rows), (std::vector<size_t>{1, 2, 4, 6, 10}));

    // A year of equal Evd: the earlier half.
    const std::vector<size_t> flat = en17037DaylightHours(calendarYear());
    QCOMPARE(flat.size(), size_t(4380));
    QCOMPARE(flat.front(), size_t(0));
    QCOMPARE(flat.back(), size_t(4379));
    QCOMPARE(en17037DaylightHours(calendarYear(true)).size(), size_t(4392));
    QVERIFY(en17037DaylightHours({}).empty());
}

void TestAnnualMetrics::en17037LevelsFromConstructedHours() {
    // Evd: 8000 lx in the rows ending at 06:00 to 19:00 (14 a day, 5110 of them), 9000 lx on
    // 31 December at noon, 0 otherwise. The 4380 daylight hours are the 9000 lx row and the first
    // 4379 of the tied 8000 lx rows (the ties go to earlier rows).
    std::vector<AnnualHour> year = calendarYear();
    for (AnnualHour& h : year)
        if (h.hour >= 6 && h.hour <= 19) h.diffuseIlluminanceLux = 8000;
    const size_t lastNoon = 364 * 24 + 11;
    QCOMPARE(year[lastNoon].month, 12);
    QCOMPARE(year[lastNoon].day, 31);
    QCOMPARE(year[lastNoon].hour, 12);
    year[lastNoon].diffuseIlluminanceLux = 9000;
    std::vector<size_t> expected;
    for (size_t h = 0; h < year.size(); ++h)
        if (year[h].diffuseIlluminanceLux == 8000 && expected.size() < 4379) expected.push_back(h);
    expected.push_back(lastNoon);
    const std::vector<size_t> daylight = en17037DaylightHours(year);
    QCOMPARE(daylight, expected);

    // 20 points on the plane and two inside geometry: point 20 dark, point 21 at 1000 lx, which
    // would lift the plane if it counted. With j counting the daylight hours in row order:
    //  A, j < 2189: points 0-9 at 500 lx, 10-18 at 300, 19 at 100;
    //  B, j = 2189: points 0-8 at 500, 9-18 at 300, 19 at 100;
    //  C, j >= 2190: points 0-8 at 500, 9-17 at 300, 18-19 at 99.
    // Every other hour has all points at 1000 lx, which would lift every level if it counted.
    // Points at >= 750 / 500 / 300 / 100 lx: A 0 / 10 / 19 / 20, B 0 / 9 / 19 / 20, C 0 / 9 / 18 / 18;
    // half the plane is 10 points, 95% is 19.
    //  minimum (300 on half, 100 on 95%): target in all hours, minimum in A and B: 2190 of 4380, met;
    //  medium (500 on half, 300 on 95%): target in A only (2189 hours), minimum in A and B (2190):
    //    fails on its target fraction alone;
    //  high (750 on half, 500 on 95%): neither in any hour.
    constexpr size_t kPoints = 22;
    Matrix lux(year.size(), kPoints, 1000.0f);
    for (size_t j = 0; j < expected.size(); ++j) {
        const size_t h = expected[j];
        const char type = j < 2189 ? 'A' : j == 2189 ? 'B' : 'C';
        const size_t at500 = type == 'A' ? 10 : 9;
        const size_t at300 = type == 'C' ? 18 : 19;
        for (size_t p = 0; p < 20; ++p)
            lux.at(h, p) = p < at500 ? 500.0f : p < at300 ? 300.0f : type == 'C' ? 99.0f : 100.0f;
        lux.at(h, 20) = 0.0f;
    }
    std::vector<uint8_t> counted(kPoints, 1);
    counted[20] = counted[21] = 0;
    const AnnualMetrics m = computeAnnualMetrics(year, kPoints, lux.values, {}, Occupancy{}, counted);
    QCOMPARE(m.daylightHours, 4380);

    const En17037Level& minimum = m.en17037[0];
    QCOMPARE(minimum.name, std::string("minimum"));
    QCOMPARE(minimum.targetLux, 300.0);
    QCOMPARE(minimum.minimumTargetLux, 100.0);
    QVERIFY_NEAR(minimum.fractionTarget, 1.0);
    QVERIFY_NEAR(minimum.fractionMinimum, 0.5);
    QVERIFY(minimum.met);

    const En17037Level& medium = m.en17037[1];
    QCOMPARE(medium.name, std::string("medium"));
    QCOMPARE(medium.targetLux, 500.0);
    QCOMPARE(medium.minimumTargetLux, 300.0);
    QVERIFY_NEAR(medium.fractionTarget, 2189.0 / 4380);
    QVERIFY_NEAR(medium.fractionMinimum, 0.5);
    QVERIFY(!medium.met);

    const En17037Level& high = m.en17037[2];
    QCOMPARE(high.name, std::string("high"));
    QCOMPARE(high.targetLux, 750.0);
    QCOMPARE(high.minimumTargetLux, 500.0);
    QVERIFY_NEAR(high.fractionTarget, 0.0);
    QVERIFY_NEAR(high.fractionMinimum, 0.0);
    QVERIFY(!high.met);

    // Counting the two other points too (22: half is 11 points, 95% is 20.9, so 21), the bright one
    // adds one point at every level and the dark one none: 500 lx on 11 points in A only, 100 lx on
    // 21 in A and B, 300 lx on 21 in no hour.
    const AnnualMetrics all = computeAnnualMetrics(year, kPoints, lux.values, {}, Occupancy{});
    QCOMPARE(all.countedPoints, 22);
    QVERIFY_NEAR(all.en17037[0].fractionTarget, 1.0);
    QVERIFY_NEAR(all.en17037[0].fractionMinimum, 0.5);
    QVERIFY_NEAR(all.en17037[1].fractionTarget, 2189.0 / 4380);
    QVERIFY_NEAR(all.en17037[1].fractionMinimum, 0.0);
}

void TestAnnualMetrics::mismatchedSizesThrow() {
    const std::vector<AnnualHour> year = calendarYear();
    const std::vector<float> lux(year.size() * 3, 0.0f);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, computeAnnualMetrics(year, 4, lux, {}, Occupancy{}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             computeAnnualMetrics(year, 3, lux, std::vector<float>(10, 0.0f), Occupancy{}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             computeAnnualMetrics(year, 3, lux, {}, Occupancy{}, std::vector<uint8_t>(2, 1)));
}

void TestAnnualMetrics::fullYearOfAThousandPoints() {
    // Point p at p lx every hour: DA300 1 from point 300 up (70%), UDI fell short below 100 (10%);
    // 300 lx on at least half the plane every hour, 100 lx on 90% of it, short of 95%.
    constexpr size_t kPoints = 1000;
    const std::vector<AnnualHour> year = calendarYear();
    std::vector<float> lux(year.size() * kPoints);
    for (size_t h = 0; h < year.size(); ++h)
        for (size_t p = 0; p < kPoints; ++p) lux[h * kPoints + p] = float(p);
    const std::vector<float> sun(lux.size(), 0.0f);
    const AnnualMetrics m = computeAnnualMetrics(year, kPoints, lux, sun, Occupancy{});
    QVERIFY_NEAR(m.sda300, 70.0);
    QVERIFY_NEAR(m.udiFellShort, 0.1);
    QVERIFY_NEAR(m.udiExceeded, 0.0);
    QVERIFY_NEAR(m.en17037[0].fractionTarget, 1.0);
    QVERIFY_NEAR(m.en17037[0].fractionMinimum, 0.0);
    QVERIFY(!m.en17037[0].met);
}

QTEST_GUILESS_MAIN(TestAnnualMetrics)
#include "test_annual_metrics.moc"
