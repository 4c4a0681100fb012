// Daylight particles through the windows (render/trace/lights/daylight_portals.h): the density
// sampleLine() reports is the one lineDensity() evaluates and it is the lines' true density
// (over the plane across the direction, the mean of 1 / p is the disc's area and the mean of
// [crosses pane k] / p is the pane's projected area, within their Monte Carlo error), for panes
// with a known outside and an unknown one; and RenderScene traces which side of a room's window
// and door is outside (a free-standing pane stays unknown).

#include "core/scene/room_geometry.h"
#include "core/scene/scene_io.h"
#include "render/trace/lights/daylight_portals.h"
#include "render/trace/render_scene.h"
#include "render/trace/rng.h"

#include <QtTest>

#include <cmath>

using namespace lucerna;

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
    void sampledLinesHaveTheirDensity();
    void outsideSideIsTraced();
};

void TestDaylightPortals::sampledLinesHaveTheirDensity() {
    // A window in the plane x = 2 (outside: +x), 1 x 1.5, and a skylight in y = 3 whose
    // outside is unknown, 2 x 1; the scene's sphere of radius 5 about the origin.
    std::vector<Portal> portals;
    addQuad(portals, V3f(2, 1, -0.5f), V3f(2, 1, 0.5f), V3f(2, 2.5f, 0.5f), V3f(2, 2.5f, -0.5f), 0);
    for (Portal& p : portals) p.outside = p.normal.x > 0 ? 1 : -1;  // the side facing +x
    addQuad(portals, V3f(-1, 3, -0.5f), V3f(1, 3, -0.5f), V3f(1, 3, 0.5f), V3f(-1, 3, 0.5f), 0);
    const float radius = 5;
    const DaylightPortals dp(portals, V3f(0, 0, 0), radius);
    QVERIFY(!dp.empty());
    const V3f windowLo(2, 1, -0.5f), windowHi(2, 2.5f, 0.5f), skyLo(-1, 3, -0.5f), skyHi(1, 3, 0.5f);
    const V3f directions[] = {V3f(1, 1, 0.3f).normalized(), V3f(-1, 0.5f, 0).normalized(), V3f(0, 1, 0),
                              V3f(0.8f, -0.2f, 0.1f).normalized()};
    for (const V3f& w : directions) {
        const int n = 200000;
        Rng rng(11);
        double sumInv = 0, sumInv2 = 0, window = 0, window2 = 0, sky = 0, sky2 = 0;
        for (int i = 0; i < n; ++i) {
            float density = 0;
            const V3f point = dp.sampleLine(w, rng.next2D(), density);
            QVERIFY(density > 0);
            QVERIFY2(std::abs(dp.lineDensity(point, w) / density - 1) < 1e-6, "sampleLine's density is lineDensity's");
            const double inv = 1.0 / density;
            sumInv += inv;
            sumInv2 += inv * inv;
            const double win = crossesRectangle(point, w, 0, 2, windowLo, windowHi) ? inv : 0;
            const double sk = crossesRectangle(point, w, 1, 3, skyLo, skyHi) ? inv : 0;
            window += win;
            window2 += win * win;
            sky += sk;
            sky2 += sk * sk;
        }
        const auto check = [&](const char* what, double sum, double sum2, double expected) {
            const double mean = sum / n, error = 4 * std::sqrt(std::max(sum2 / n - mean * mean, 0.0) / n) + 1e-9;
            QVERIFY2(std::abs(mean - expected) < error,
                     qPrintable(QString("w (%1, %2, %3), %4: %5 against %6 (+- %7)").arg(w.x).arg(w.y).arg(w.z)
                                    .arg(what).arg(mean).arg(expected).arg(error)));
        };
        check("disc area", sumInv, sumInv2, kPi * radius * radius);
        check("window's projected area", window, window2, 1.5 * std::abs(w.x));
        check("skylight's projected area", sky, sky2, 2.0 * std::abs(w.y));
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

QTEST_GUILESS_MAIN(TestDaylightPortals)
#include "test_daylight_portals.moc"
