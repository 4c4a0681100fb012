// How many daylight particles enter a room (render/trace/lights/particle_entry.h): in a closed
// box lit through one skylight, a particle counts as inside exactly when its first ray crossed
// the pane (the only way in), with daylight particles through the windows most do and from the
// disc few, and both ways estimate the same emitted power and the same power entering. The box
// of a scene's drawn rooms.

#include "core/scene/scene_io.h"
#include "render/trace/lights/particle_entry.h"
#include "render/trace/rng.h"

#include <QtTest>

#include <cmath>

using namespace lucerna;

namespace {

// A closed 4 x 2.8 x 3 m box (walls of zero thickness) under a uniform sky, lit through a
// 1.5 x 1.5 m skylight in its roof, the room drawn with the box's outline.
Scene skylitBox() {
    return parseScene(R"({"lucerna": 1, "camera": {"position": [2, 1.5, 1.5], "target": [2, 1.5, 3], "fov_y": 60, "resolution": [8, 8]},
      "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}, "pane": {"type": "glazing", "transmittance": [0.7, 0.7, 0.7]}},
      "objects": [
        {"name": "floor", "material": "grey", "mesh": {"quad": [[0, 0, 0], [0, 0, 3], [4, 0, 3], [4, 0, 0]]}},
        {"name": "north", "material": "grey", "mesh": {"quad": [[0, 0, 0], [4, 0, 0], [4, 2.8, 0], [0, 2.8, 0]]}},
        {"name": "south", "material": "grey", "mesh": {"quad": [[0, 0, 3], [0, 2.8, 3], [4, 2.8, 3], [4, 0, 3]]}},
        {"name": "west", "material": "grey", "mesh": {"quad": [[0, 0, 0], [0, 2.8, 0], [0, 2.8, 3], [0, 0, 3]]}},
        {"name": "east", "material": "grey", "mesh": {"quad": [[4, 0, 0], [4, 0, 3], [4, 2.8, 3], [4, 2.8, 0]]}},
        {"name": "roof west", "material": "grey", "mesh": {"quad": [[0, 2.8, 0], [1.25, 2.8, 0], [1.25, 2.8, 3], [0, 2.8, 3]]}},
        {"name": "roof east", "material": "grey", "mesh": {"quad": [[2.75, 2.8, 0], [4, 2.8, 0], [4, 2.8, 3], [2.75, 2.8, 3]]}},
        {"name": "roof north", "material": "grey", "mesh": {"quad": [[1.25, 2.8, 0], [2.75, 2.8, 0], [2.75, 2.8, 0.75], [1.25, 2.8, 0.75]]}},
        {"name": "roof south", "material": "grey", "mesh": {"quad": [[1.25, 2.8, 2.25], [2.75, 2.8, 2.25], [2.75, 2.8, 3], [1.25, 2.8, 3]]}},
        {"name": "skylight", "material": "pane", "mesh": {"quad": [[1.25, 2.8, 0.75], [2.75, 2.8, 0.75], [2.75, 2.8, 2.25], [1.25, 2.8, 2.25]]}}],
      "rooms": [{"name": "box", "outline": [[0, 0], [4, 0], [4, 3], [0, 3]], "floor_level": 0, "height": 2.8,
                 "materials": {"floor": "grey", "walls": "grey", "ceiling": "grey"}}],
      "sky": {"model": "uniform", "zenith_luminance": 1000}})",
                      std::string(LUCERNA_RESOURCE_DIR) + "/scenes/case.json");
}

// The daylight particles among the first `draws` that the scene's sampler sends, as
// countParticleEntry draws them, whose first ray crosses a pane: in a closed box with one pane,
// those that get in.
int64_t crossingThePane(const RenderScene& scene, int64_t draws, uint64_t seed) {
    int64_t crossing = 0;
    for (int64_t i = 0; i < draws; ++i) {
        Rng rng(seed, uint64_t(i));
        const V2f uPosition = rng.next2D(), uDirection = rng.next2D();
        EmissionSample es;
        if (!scene.lights().sampleEmission(uPosition, uDirection, rng.next1D(), es) || !es.environment) continue;
        Rgb through(1, 1, 1);
        if (scene.intersect(Ray{es.position, es.direction}, nullptr, &through) && through.y < 1) ++crossing;
    }
    return crossing;
}

}  // namespace

class TestParticleEntry : public QObject {
    Q_OBJECT
private slots:
    void portalsSendParticlesIn();
    void roomsBox();
};

void TestParticleEntry::portalsSendParticlesIn() {
    const SceneSnapshot box = std::make_shared<const Scene>(skylitBox());
    const RoomBox room = *drawnRoomsBox(*box);
    const int64_t n = 40000;
    const RenderScene disc(box, 8, 8, nullptr, kDefaultLightSelection, false);
    const RenderScene portals(box, 8, 8, nullptr, kDefaultLightSelection, true);
    const ParticleEntry off = countParticleEntry(disc, room, n, 7), on = countParticleEntry(portals, room, n, 7);
    for (const ParticleEntry* e : {&off, &on}) {
        QCOMPARE(e->particles, n);
        QCOMPARE(e->draws, n);  // the sky is the only light
    }
    QCOMPARE(off.inside, crossingThePane(disc, n, 7));
    QCOMPARE(on.inside, crossingThePane(portals, n, 7));
    const double fractionOff = double(off.inside) / double(n), fractionOn = double(on.inside) / double(n);
    QVERIFY2(fractionOn >= 0.5, qPrintable(QString("portals on: %1 of the particles enter").arg(fractionOn)));
    QVERIFY2(fractionOff < 0.2, qPrintable(QString("portals off: %1 of the particles enter").arg(fractionOff)));
    QCOMPARE(off.facing, int64_t(0));  // no portal without the option
    // Unbiased both ways: the same emitted power (within 4 standard errors) and the same share
    // of it entering (the disc's few particles in make that one within about 3%).
    const auto mean = [&](const ParticleEntry& e) { return e.power / double(e.draws); };
    const auto error = [&](const ParticleEntry& e) {
        return std::sqrt(std::max(e.powerSquared / double(e.draws) - mean(e) * mean(e), 0.0) / double(e.draws));
    };
    QVERIFY2(std::abs(mean(on) - mean(off)) < 4 * std::hypot(error(on), error(off)),
             qPrintable(QString("emitted power: %1 (on) against %2 (off)").arg(mean(on)).arg(mean(off))));
    const double inOff = off.powerInside / off.power, inOn = on.powerInside / on.power;
    QVERIFY2(std::abs(inOn / inOff - 1) < 0.12, qPrintable(QString("power entering: %1 (on) against %2 (off)").arg(inOn).arg(inOff)));
}

void TestParticleEntry::roomsBox() {
    Scene scene = skylitBox();
    const std::optional<RoomBox> box = drawnRoomsBox(scene);
    QVERIFY(box);
    QCOMPARE(box->lo, V3f(0, 0, 0));
    QCOMPARE(box->hi, V3f(4, 2.8f, 3));
    scene.rooms.push_back(Room{"annex", {{4, -1}, {6, -1}, {6, 3}, {4, 3}}, 0.5, 3.0, "grey", "grey", "grey", {}});
    QCOMPARE(drawnRoomsBox(scene)->lo, V3f(0, 0, -1));
    QCOMPARE(drawnRoomsBox(scene)->hi, V3f(6, 3.5f, 3));
    scene.rooms.clear();
    QVERIFY(!drawnRoomsBox(scene));
}

QTEST_GUILESS_MAIN(TestParticleEntry)
#include "test_particle_entry.moc"
