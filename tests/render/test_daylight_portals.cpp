// Daylight particles through the windows (render/trace/lights/daylight_portals.h): the density
// sample() reports is the one lineDensity() evaluates, and it is the particles' true joint
// density of direction and line (the power of all lines, and of the lines through each pane, is
// the same as with the environment's own directions and lines, within their Monte Carlo error),
// for panes with a known outside and an unknown one, a sun disc and none; and RenderScene traces
// which side of a room's window and door is outside (a free-standing pane stays unknown).

#include "daylight_scenes.h"

#include "core/scene/room_geometry.h"
#include "core/scene/scene_io.h"
#include "render/trace/lights/daylight_portals.h"
#include "render/trace/render_scene.h"
#include "render/trace/rng.h"

#include <QtTest>

#include <cmath>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// A quad as two portal triangles.
void addQuad(std::vector<Portal>& out, const V3f& a, const V3f& b, const V3f& c, const V3f& d, int8_t outside) {
    for (const auto& [p0, p1, p2] : {std::array<V3f, 3>{a, b, c}, std::array<V3f, 3>{a, c, d}}) {
        const V3f n = (p1 - p0).cross(p2 - p0);
        out.push_back({p0, p1, p2, n.normalized(), 0.5f * n.length(), outside});
    }
}

// Whether the line through o along d crosses the axis-aligned rectangle at coordinate `axis` =
// level, within [lo, hi] on the other two axes.
bool crossesRectangle(const V3f& o, const V3f& d, int axis, float level, const V3f& lo, const V3f& hi) {
    if (std::abs(d[axis]) < 1e-12f) return false;
    const V3f p = o + d * ((level - o[axis]) / d[axis]);
    for (int k = 0; k < 3; ++k)
        if (k != axis && (p[k] < lo[k] || p[k] > hi[k])) return false;
    return true;
}

}  // namespace

class TestDaylightPortals : public QObject {
    Q_OBJECT
private slots:
    void particlesHaveTheirDensity();
    void particlesHaveTheirDensity_data();
    void parallelLinesHaveTheirDensity();
    void outsideSideIsTraced();
    void markedOpeningIsAPortal();
};

void TestDaylightPortals::particlesHaveTheirDensity() {
    // A window in the plane x = 2 (outside: +x), 1 x 1.5, and a skylight in y = 3 whose outside
    // is unknown, 2 x 1; the scene's sphere of radius 5 about the origin; a CIE clear sky with a
    // sun disc in front of the window.
    QFETCH(int, skyType);
    QFETCH(double, sunDiameter);
    const auto environment = cieEnvironment(skyType, 10000, V3d(-0.7, -0.5, -0.2), 80000, sunDiameter);
    QVERIFY(environment.has_value());
    std::vector<Portal> portals;
    addQuad(portals, V3f(2, 1, -0.5f), V3f(2, 1, 0.5f), V3f(2, 2.5f, 0.5f), V3f(2, 2.5f, -0.5f), 0);
    for (Portal& p : portals) p.outside = p.normal.x > 0 ? 1 : -1;  // the side facing +x
    addQuad(portals, V3f(-1, 3, -0.5f), V3f(1, 3, -0.5f), V3f(1, 3, 0.5f), V3f(-1, 3, 0.5f), 0);
    const float radius = 5;
    const DaylightPortals dp(portals, *environment, V3f(0, 0, 0), radius);
    QVERIFY(!dp.empty());
    const V3f windowLo(2, 1, -0.5f), windowHi(2, 2.5f, 0.5f), skyLo(-1, 3, -0.5f), skyHi(1, 3, 0.5f);

    // Each estimate's mean over n particles, by the portals and by the environment alone (the
    // disc): the power of all lines, of the lines crossing the window and of those crossing the
    // skylight. Equal means within their errors say the joint density is the true one.
    struct Mean {
        double sum = 0, sum2 = 0;
        void add(double x) { sum += x, sum2 += x * x; }
    };
    const int n = 300000;
    Mean portalAll, portalWindow, portalSky, discAll, discWindow, discSky;
    Rng rng(11);
    int throughPortals = 0;
    for (int i = 0; i < n; ++i) {
        DaylightParticle p;
        if (!dp.sample(rng.next2D(), rng.next2D(), p)) {
            for (Mean* m : {&portalAll, &portalWindow, &portalSky}) m->add(0);
        } else {
            QVERIFY2(std::abs(dp.lineDensity(p.point, p.towardSky) / p.lineDensity - 1) < 1e-5,
                     "sample()'s line density is lineDensity()'s");
            QVERIFY(p.pdfDirection > 0 && std::abs(environment->pdf(p.towardSky) / p.pdfDirection - 1) < 1e-5);
            QVERIFY((p.point - V3f(0, 0, 0)).length() >= radius * 0.999f);  // starts outside the scene
            const double value = luminance(p.radiance) / (double(p.pdfDirection) * p.lineDensity);
            const bool window = crossesRectangle(p.point, p.towardSky, 0, 2, windowLo, windowHi);
            const bool skylight = crossesRectangle(p.point, p.towardSky, 1, 3, skyLo, skyHi);
            throughPortals += (window && p.towardSky.x > 0) || skylight;
            portalAll.add(value);
            portalWindow.add(window ? value : 0);
            portalSky.add(skylight ? value : 0);
        }
        // The reference: the environment's own directions, lines by the window's and the
        // skylight's projected area (exact given the direction).
        V3f w;
        float pdf = 0;
        Rgb L;
        if (!environment->sample(rng.next2D(), w, pdf, L)) {
            for (Mean* m : {&discAll, &discWindow, &discSky}) m->add(0);
            continue;
        }
        const double value = luminance(L) / pdf;
        discAll.add(value * kPi * radius * radius);
        discWindow.add(value * 1.5 * std::abs(w.x));
        discSky.add(value * 2.0 * std::abs(w.y));
    }
    const auto agree = [&](const char* what, const Mean& a, const Mean& b) {
        const double ma = a.sum / n, mb = b.sum / n;
        const double va = std::max(a.sum2 / n - ma * ma, 0.0) / n, vb = std::max(b.sum2 / n - mb * mb, 0.0) / n;
        const double error = 4 * std::sqrt(va + vb);
        QVERIFY2(std::abs(ma - mb) < error && mb > 0,
                 qPrintable(QString("%1: through the portals %2, the environment alone %3 (+- %4)")
                                .arg(what).arg(ma).arg(mb).arg(error)));
    };
    agree("every line", portalAll, discAll);
    agree("lines through the window", portalWindow, discWindow);
    agree("lines through the skylight", portalSky, discSky);
    // Three quarters are drawn through a portal that faces them; a few from the disc cross one too.
    QVERIFY2(throughPortals > 0.72 * n, qPrintable(QString("%1 of %2 through a portal").arg(throughPortals).arg(n)));
}

void TestDaylightPortals::particlesHaveTheirDensity_data() {
    QTest::addColumn<int>("skyType");
    QTest::addColumn<double>("sunDiameter");
    QTest::newRow("clear sky, sun disc") << 12 << 0.53;
    QTest::newRow("overcast sky, delta sun") << 1 << 0.0;
}

void TestDaylightPortals::parallelLinesHaveTheirDensity() {
    // A directional light's particles (a sun of diameter 0): over the plane across w, the mean of
    // 1 / p is the disc's area and the mean of [crosses the window] / p the window's projected
    // area; toward a w the window does not face, every line comes from the disc.
    const auto environment = cieEnvironment(1, 10000);
    QVERIFY(environment.has_value());
    std::vector<Portal> portals;
    addQuad(portals, V3f(2, 1, -0.5f), V3f(2, 1, 0.5f), V3f(2, 2.5f, 0.5f), V3f(2, 2.5f, -0.5f), 0);
    for (Portal& p : portals) p.outside = p.normal.x > 0 ? 1 : -1;  // the side facing +x
    const float radius = 5;
    const DaylightPortals dp(portals, *environment, V3f(0, 0, 0), radius);
    const V3f windowLo(2, 1, -0.5f), windowHi(2, 2.5f, 0.5f);
    for (const V3f& w : {V3f(1, 1, 0.3f).normalized(), V3f(-1, 0.5f, 0).normalized()}) {
        const int n = 200000;
        Rng rng(5);
        double sumInv = 0, sumInv2 = 0, window = 0, window2 = 0;
        for (int i = 0; i < n; ++i) {
            float density = 0;
            const V3f point = dp.sampleParallel(w, rng.next2D(), density);
            QVERIFY(density > 0 && std::abs(dp.parallelDensity(point, w) / density - 1) < 1e-6);
            const double inv = 1.0 / density, win = crossesRectangle(point, w, 0, 2, windowLo, windowHi) ? inv : 0;
            sumInv += inv;
            sumInv2 += inv * inv;
            window += win;
            window2 += win * win;
        }
        const auto check = [&](const char* what, double sum, double sum2, double expected) {
            const double mean = sum / n, error = 4 * std::sqrt(std::max(sum2 / n - mean * mean, 0.0) / n) + 1e-9;
            QVERIFY2(std::abs(mean - expected) < error,
                     qPrintable(QString("w (%1, %2, %3), %4: %5 against %6 (+- %7)").arg(w.x).arg(w.y).arg(w.z)
                                    .arg(what).arg(mean).arg(expected).arg(error)));
        };
        check("disc area", sumInv, sumInv2, kPi * radius * radius);
        check("window's projected area", window, window2, 1.5 * std::abs(w.x));
    }
}

void TestDaylightPortals::outsideSideIsTraced() {
    // A drawn 4 x 3 x 2.8 m room with a glazed window in wall 1 (z = 0, the outside at -z) and a
    // door in wall 2 (x = 4, the outside at +x), a hole that is a portal too, under a sky, and a
    // pane standing free in the open beside it.
    Scene loaded = parseScene(R"({"lucerna": 1, "camera": {"position": [2, 1.5, 1.5], "target": [2, 1.5, 3], "fov_y": 60, "resolution": [8, 8]},
      "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}, "pane": {"type": "glazing", "transmittance": [0.7, 0.7, 0.7]}},
      "objects": [{"name": "free pane", "material": "pane", "mesh": {"quad": [[10, 0, 0], [10, 2, 0], [12, 2, 0], [12, 0, 0]]}}],
      "rooms": [{"name": "office", "outline": [[0, 0], [4, 0], [4, 3], [0, 3]], "floor_level": 0, "height": 2.8,
                 "materials": {"floor": "grey", "walls": "grey", "ceiling": "grey"},
                 "openings": [{"type": "window", "wall": 1, "offset": 1, "sill": 0.9, "width": 2, "height": 1.2, "glazing": "pane"},
                              {"type": "door", "wall": 2, "offset": 1, "width": 0.9, "height": 2.1}]}],
      "sky": {"model": "cie_overcast", "zenith_luminance": 1000}})",
                              std::string(LUCERNA_RESOURCE_DIR) + "/scenes/case.json");
    std::set<std::string> taken;
    const std::vector<Object> surfaces = roomSurfaces(loaded.rooms[0], loaded, taken);
    loaded.objects.insert(loaded.objects.end(), surfaces.begin(), surfaces.end());
    const RenderScene scene(std::make_shared<const Scene>(std::move(loaded)), 8, 8, nullptr, kDefaultLightSelection, true);
    const std::vector<Portal>& portals = scene.lights().particlePortals().portals();
    QCOMPARE(portals.size(), size_t(6));
    int window = 0, free = 0, door = 0;
    for (const Portal& p : portals) {
        const V3f centre = (p.p0 + p.p1 + p.p2) / 3.0f;
        if (centre.x > 9) {
            QCOMPARE(int(p.outside), 0);  // open on both sides
            ++free;
        } else if (std::abs(centre.x - 4) < 1e-4f) {
            QVERIFY(centre.z > 1 && centre.z < 1.9f && centre.y < 2.1f);
            QCOMPARE(int(p.outside), p.normal.x > 0 ? 1 : -1);
            ++door;
        } else {
            // The side whose normal points to -z, away from the room, is outside.
            QCOMPARE(int(p.outside), p.normal.z < 0 ? 1 : -1);
            ++window;
        }
    }
    QCOMPARE(window, 2);
    QCOMPARE(free, 2);
    QCOMPARE(door, 2);
    // Without daylight particles through the windows (option daylight_portals=off, the default), none.
    const RenderScene disc(scene.snapshot(), 8, 8, nullptr, kDefaultLightSelection, false);
    QVERIFY(disc.lights().particlePortals().empty());
}

void TestDaylightPortals::markedOpeningIsAPortal() {
    // A closed 4 x 3 x 2.8 m box of an imported model's kind (plain objects, no drawn room) whose
    // wall z = 0 has a 2 x 1.2 m hole, filled by a quad marked as an opening.
    const std::string text = R"({"lucerna": 1, "camera": {"position": [2, 1.5, 1.5], "target": [2, 1.5, 3], "fov_y": 60, "resolution": [8, 8]},
      "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
      "objects": [
        {"name": "floor", "material": "grey", "mesh": {"quad": [[0, 0, 0], [4, 0, 0], [4, 0, 3], [0, 0, 3]]}},
        {"name": "ceiling", "material": "grey", "mesh": {"quad": [[0, 2.8, 0], [4, 2.8, 0], [4, 2.8, 3], [0, 2.8, 3]]}},
        {"name": "back", "material": "grey", "mesh": {"quad": [[0, 0, 3], [4, 0, 3], [4, 2.8, 3], [0, 2.8, 3]]}},
        {"name": "left", "material": "grey", "mesh": {"quad": [[0, 0, 0], [0, 0, 3], [0, 2.8, 3], [0, 2.8, 0]]}},
        {"name": "right", "material": "grey", "mesh": {"quad": [[4, 0, 0], [4, 0, 3], [4, 2.8, 3], [4, 2.8, 0]]}},
        {"name": "front below", "material": "grey", "mesh": {"quad": [[0, 0, 0], [4, 0, 0], [4, 0.9, 0], [0, 0.9, 0]]}},
        {"name": "front above", "material": "grey", "mesh": {"quad": [[0, 2.1, 0], [4, 2.1, 0], [4, 2.8, 0], [0, 2.8, 0]]}},
        {"name": "front left", "material": "grey", "mesh": {"quad": [[0, 0.9, 0], [1, 0.9, 0], [1, 2.1, 0], [0, 2.1, 0]]}},
        {"name": "front right", "material": "grey", "mesh": {"quad": [[3, 0.9, 0], [4, 0.9, 0], [4, 2.1, 0], [3, 2.1, 0]]}},
        {"name": "window opening", "material": "grey", "portal": true, "mesh": {"quad": [[1, 0.9, 0], [3, 0.9, 0], [3, 2.1, 0], [1, 2.1, 0]]}}],
      "sky": {"model": "cie_overcast", "zenith_luminance": 1000}})";
    const std::string path = std::string(LUCERNA_RESOURCE_DIR) + "/scenes/case.json";
    Scene loaded = parseScene(text, path);
    QVERIFY(loaded.objects.back().portal && !loaded.objects.front().portal);
    const Scene again = parseScene(saveSceneToString(loaded), path);  // the key survives a save
    QVERIFY(again.objects.back().portal && !again.objects.front().portal);
    try {
        parseScene(QString::fromStdString(text).replace("\"portal\": true", "\"portal\": 1").toStdString(), path);
        QFAIL("a portal key that is not a boolean was accepted");
    } catch (const std::exception& e) {
        QVERIFY2(QString(e.what()).contains("portal"), e.what());
    }

    const RenderScene scene(std::make_shared<const Scene>(std::move(loaded)), 8, 8, nullptr, kDefaultLightSelection, true);
    // The opening's two triangles are the portals, their outside (-z) traced.
    const std::vector<Portal>& portals = scene.lights().particlePortals().portals();
    QCOMPARE(portals.size(), size_t(2));
    for (const Portal& p : portals) QCOMPARE(int(p.outside), p.normal.z < 0 ? 1 : -1);
    // Rays cross it untouched; the wall beside it still stops them.
    const Ray out{V3f(2, 1.5f, 1.5f), V3f(0, 0, -1)};
    QVERIFY(!scene.intersect(out));
    QVERIFY(scene.transmittance(out) == Rgb(1, 1, 1));
    QVERIFY(scene.intersect(Ray{V3f(0.5f, 1.5f, 1.5f), V3f(0, 0, -1)}));
    // Without the mark the quad is a wall like the others: no portal, rays stop at it.
    Scene closed = parseScene(text, path);
    closed.objects.back().portal = false;
    const RenderScene shut(std::make_shared<const Scene>(std::move(closed)), 8, 8, nullptr, kDefaultLightSelection, true);
    QVERIFY(shut.lights().particlePortals().empty());
    QVERIFY(shut.intersect(out));
}

QTEST_GUILESS_MAIN(TestDaylightPortals)
#include "test_daylight_portals.moc"
