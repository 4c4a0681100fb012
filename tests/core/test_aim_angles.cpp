// A light's aim as tilt and azimuth (core/scene/aim_angles.h): the conventions by hand, and the
// round trip to the scene's direction vector over many directions and several norths.

#include "core/scene/aim_angles.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace lucerna;

namespace {
bool near(const V3d& a, const V3d& b, double tolerance) { return (a - b).length() <= tolerance; }
QString str(const V3d& v) { return QString("(%1, %2, %3)").arg(v.x, 0, 'g', 17).arg(v.y, 0, 'g', 17).arg(v.z, 0, 'g', 17); }
}  // namespace

class TestAimAngles : public QObject {
    Q_OBJECT
private slots:
    void conventionsByHand();
    void roundTripOfManyDirections();
    void siteNorth();
};

void TestAimAngles::conventionsByHand() {
    const V3d north(0, 0, -1);
    // Straight down is tilt 0 (whatever its length), straight up 180; neither has a bearing.
    AimAngles a = aimAngles(V3d(0, -3, 0), north);
    QCOMPARE(a.tiltDeg, 0.0);
    QCOMPARE(a.azimuthDeg, 0.0);
    a = aimAngles(V3d(0, 2, 0), north);
    QCOMPARE(a.tiltDeg, 180.0);
    QCOMPARE(a.azimuthDeg, 0.0);
    QVERIFY(near(aimDirection({0, 123}, north), V3d(0, -1, 0), 1e-15));
    // Horizontal toward north (-z), east (+x), south (+z), west (-x).
    const struct { V3d d; double azimuth; } compass[] = {
        {V3d(0, 0, -1), 0}, {V3d(1, 0, 0), 90}, {V3d(0, 0, 1), 180}, {V3d(-1, 0, 0), 270}};
    for (const auto& c : compass) {
        a = aimAngles(c.d, north);
        QVERIFY2(std::abs(a.tiltDeg - 90) < 1e-12, qPrintable(str(c.d)));
        QVERIFY2(std::abs(a.azimuthDeg - c.azimuth) < 1e-12, qPrintable(QString("%1 vs %2").arg(a.azimuthDeg).arg(c.azimuth)));
        QVERIFY(near(aimDirection(a, north), c.d, 1e-15));
    }
    // 30 degrees from down, leaning east.
    a = aimAngles(V3d(std::sin(M_PI / 6), -std::cos(M_PI / 6), 0), north);
    QVERIFY(std::abs(a.tiltDeg - 30) < 1e-12);
    QVERIFY(std::abs(a.azimuthDeg - 90) < 1e-12);
    // Azimuths past a turn, and tilts past the ends, are the same aims.
    QVERIFY(near(aimDirection({40, 370}, north), aimDirection({40, 10}, north), 1e-15));
    QVERIFY(near(aimDirection({40, -90}, north), aimDirection({40, 270}, north), 1e-15));
    QVERIFY(near(aimDirection({190, 0}, north), V3d(0, 1, 0), 1e-15));
}

void TestAimAngles::roundTripOfManyDirections() {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> gauss;
    const V3d norths[] = {V3d(0, 0, -1), V3d(1, 0, 0), V3d(std::sqrt(0.5), 0, std::sqrt(0.5))};
    for (const V3d& north : norths) {
        for (int i = 0; i < 20000; ++i) {
            V3d d(gauss(rng), gauss(rng), gauss(rng));
            if (d.length() < 1e-6) continue;
            d *= std::exp(gauss(rng));  // any length
            const AimAngles a = aimAngles(d, north);
            QVERIFY(a.tiltDeg >= 0 && a.tiltDeg <= 180);
            QVERIFY(a.azimuthDeg >= 0 && a.azimuthDeg < 360);
            const V3d back = aimDirection(a, north);
            QVERIFY2(near(back, d.normalized(), 1e-13), qPrintable(str(d) + " -> " + str(back)));
            // And the angles of the direction made are the angles given.
            const AimAngles again = aimAngles(back, north);
            QVERIFY(std::abs(again.tiltDeg - a.tiltDeg) < 1e-9);
            const double turn = std::abs(again.azimuthDeg - a.azimuthDeg);
            QVERIFY2(std::min(turn, 360 - turn) < 1e-9, qPrintable(QString("%1 vs %2").arg(again.azimuthDeg).arg(a.azimuthDeg)));
        }
    }
    // Near vertical, where an acos would lose digits: a tilt of a microdegree survives.
    const V3d north(0, 0, -1);
    const AimAngles tiny = aimAngles(aimDirection({1e-6, 45}, north), north);
    QVERIFY2(std::abs(tiny.tiltDeg - 1e-6) < 1e-12, qPrintable(QString::number(tiny.tiltDeg, 'g', 17)));
    QVERIFY(std::abs(tiny.azimuthDeg - 45) < 1e-6);
}

void TestAimAngles::siteNorth() {
    Scene scene;
    QCOMPARE(horizontalNorth(scene), V3d(0, 0, -1));
    scene.site = Site{};
    scene.site->north = V3d(2, 0, 0);
    QCOMPARE(horizontalNorth(scene), V3d(1, 0, 0));
    // With north along +x, east is north x up = +z: a light leaning toward +z has azimuth 90.
    const AimAngles a = aimAngles(V3d(0, -1, 1), horizontalNorth(scene));
    QVERIFY(std::abs(a.tiltDeg - 45) < 1e-12);
    QVERIFY(std::abs(a.azimuthDeg - 90) < 1e-12);
    scene.site->north = V3d(0, 1, 0);  // no horizontal part: the default
    QCOMPARE(horizontalNorth(scene), V3d(0, 0, -1));
}

QTEST_MAIN(TestAimAngles)
#include "test_aim_angles.moc"
