// Per-light layers (issue 7): the groups of a scene, the weights between a rendered scene and an
// edited one, and the layers of real renders: their sum is the combined image, and a mix equals
// the closed form of the scene with the changed lights (a square emitter and a point light over a
// floor, Lambert's formula and E = I cos / r^2), for several backends.

#include "closed_form_scenes.h"
#include "render/backend/light_layers/layered_backend.h"
#include "render/backend/light_layers/light_groups.h"
#include "render_helpers.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// A square emitter (radiance 2) and a point light (intensity 0.5 W/sr at (0.3, 0.6, -0.2), under
// the emitter) over a floor of albedo 0.5, seen from above.
struct EmitterAndPoint {
    RectangleOverPlane rect;
    V3d bulb{0.3, 0.6, -0.2};
    double intensity = 0.5;

    std::string json() const {
        std::string j = rect.json();
        j.insert(j.size() - 1, R"(, "lights": [{"name": "bulb", "type": "point", "position": [0.3, 0.6, -0.2], "intensity": [0.5, 0.5, 0.5]}])");
        return j;
    }
    // The floor's radiance with the emitter scaled by e and the bulb by b (per channel).
    std::vector<Rgb> expected(const Rgb& e, const Rgb& b) const {
        const std::vector<double> area = rect.expected();
        const std::vector<double> point = expectedFloorImage(rect.camera(), [&](const V3d& p) {
            const V3d d = bulb - p;
            return rect.rho / std::numbers::pi * intensity * (d.y / d.length()) / d.length2();
        });
        std::vector<Rgb> out;
        for (size_t i = 0; i < area.size(); ++i) out.push_back(e * float(area[i]) + b * float(point[i]));
        return out;
    }
};

RenderFrame renderLayered(const std::string& backend, const SceneSnapshot& scene, int spp) {
    RenderSettings s;
    s.spp = spp;
    s.seed = 7;
    auto layered = makeLayeredBackend(findBackend(backend)->make, scene, s);
    return runBackend(*layered, backend, s);
}

}  // namespace

class TestLightLayers : public QObject {
    Q_OBJECT
private slots:
    void groups() {
        const Scene scene = parseScene(EmitterAndPoint().json(), "t.json");
        const auto groups = lightGroups(scene);
        QCOMPARE(int(groups.size()), 2);
        QCOMPARE(groups[0].name, std::string("bulb"));
        QVERIFY(!groups[0].isObject);
        QCOMPARE(groups[1].name, std::string("lamp"));
        QVERIFY(groups[1].isObject);
        QCOMPARE(lightLayerChannel(groups[0], 'G'), std::string("light.bulb.G"));
        QCOMPARE(lightLayerChannel(groups[1], 'R'), std::string("emitter.lamp.R"));

        // Lit by the lamp alone: no lights, the lamp still emits; lit by the bulb: the lamp is black.
        const Scene lamp = sceneLitBy(scene, groups[1]);
        QVERIFY(lamp.lights.empty());
        QCOMPARE(lamp.findMaterial(lamp.objects[1].material)->radiance, Rgbd(2, 2, 2));
        const Scene bulb = sceneLitBy(scene, groups[0]);
        QCOMPARE(int(bulb.lights.size()), 1);
        QCOMPARE(bulb.findMaterial(bulb.objects[1].material)->radiance, Rgbd(0, 0, 0));
        QCOMPARE(bulb.objects[1].mesh, scene.objects[1].mesh);  // still there as geometry
    }

    void weights() {
        const Scene scene = parseScene(EmitterAndPoint().json(), "t.json");
        auto same = layerWeights(scene, scene);
        QVERIFY(same);
        QCOMPARE(int(same->size()), 2);
        QCOMPARE((*same)[0], Rgb(1, 1, 1));

        Scene edited = scene;
        edited.lights[0].intensity = Rgbd(1.0, 0.5, 0.0);  // brighter, redder, no blue
        edited.materials[1].radiance = Rgbd(1, 1, 1);      // the lamp at half
        auto w = layerWeights(scene, edited);
        QVERIFY(w);
        QCOMPARE((*w)[0], Rgb(2, 1, 0));
        QCOMPARE((*w)[1], Rgb(0.5f, 0.5f, 0.5f));
        // Switching a light off and on again from nothing: off scales, but a layer that was
        // rendered dark cannot be lit afterwards.
        auto back = layerWeights(edited, scene);
        QVERIFY(!back);

        Scene moved = scene;
        moved.lights[0].position.x += 0.1;
        QVERIFY(!layerWeights(scene, moved));
        Scene repainted = scene;
        repainted.materials[0].albedo = Rgbd(0.4, 0.4, 0.4);
        QVERIFY(!layerWeights(scene, repainted));
        Scene fewer = scene;
        fewer.lights.clear();
        QVERIFY(!layerWeights(scene, fewer));
    }

    // The layers of a render add up to its image, and weighted, they give the closed form of the
    // scene with the lights changed.
    void mixMatchesTheChangedScene_data() {
        QTest::addColumn<QString>("backend");
        QTest::addColumn<int>("spp");
        QTest::newRow("path") << "path" << 256;
        QTest::newRow("bdpt") << "bdpt" << 128;
        QTest::newRow("ir") << "ir" << 128;
        QTest::newRow("mlt") << "mlt" << 256;
    }
    void mixMatchesTheChangedScene() {
        QFETCH(QString, backend);
        QFETCH(int, spp);
        const EmitterAndPoint s;
        const SceneSnapshot scene = sceneFromJson(s.json());
        const RenderFrame frame = renderLayered(backend.toStdString(), scene, spp);
        const std::vector<LightGroup> groups = lightGroups(*scene);

        Image summed = frame.image;
        mixLightLayers(summed, groups, {Rgb(1, 1, 1), Rgb(1, 1, 1)});
        for (size_t i = 0; i < summed.pixelCount(); ++i)
            for (int c = 0; c < 3; ++c)
                QVERIFY(std::abs(summed.pixels[i][c] - frame.image.pixels[i][c]) <= 1e-5f * (1 + frame.image.pixels[i][c]));

        const Rgb bulbWeight(2.0f, 1.0f, 0.25f), lampWeight(0.5f, 0.5f, 0.5f);
        Image mixed = frame.image;
        mixLightLayers(mixed, groups, {bulbWeight, lampWeight});
        const std::vector<Rgb> expected = s.expected(lampWeight, bulbWeight);
        for (int c = 0; c < 3; ++c) {
            double sum = 0, sumExpected = 0;
            for (size_t i = 0; i < expected.size(); ++i) {
                sum += mixed.pixels[i][c];
                sumExpected += expected[i][c];
            }
            QVERIFY2(std::abs(sum / sumExpected - 1) < 0.02,
                     qPrintable(QString("channel %1: mean %2 of the closed form").arg(c).arg(sum / sumExpected)));
        }
    }
};

QTEST_GUILESS_MAIN(TestLightLayers)
#include "test_light_layers.moc"
