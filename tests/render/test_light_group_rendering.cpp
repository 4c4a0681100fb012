// How light groups render (issue 19; render/backend/light_layers/): a light switched off renders
// exactly as the scene without it (path and bdpt) and the file keeps it; per-group layers (one for
// a group, one for each lone light and emitter) add up to the image, switching a group off or
// scaling it whole re-mixes the layers while scaling one of its lights does not, and past 64
// layers the render is refused in one line. The groups in the window: test_light_groups.

#include "core/scene/scene.h"
#include "render/backend/light_layers/layered_backend.h"
#include "render/backend/light_layers/light_groups.h"
#include "render/engine/backend_table.h"
#include "render_helpers.h"

#include <QtTest>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace lucerna;
using namespace lucerna::test;

namespace {

// A floor seen from above, lit by three point lights, two of them in group "pair".
std::string litFloorJson(bool pairOn, bool withPair = true) {
    std::string lights = R"({"name": "solo", "type": "point", "position": [0.5, 1, 0], "intensity": [1, 1, 1]})";
    if (withPair)
        lights += std::string(R"(, {"name": "p1", "type": "point", "position": [-0.5, 0.8, 0.3], "intensity": [0.5, 0.4, 0.3], "group": "pair")") +
                  (pairOn ? "" : R"(, "on": false)") + "}" +
                  R"(, {"name": "p2", "type": "point", "position": [-0.2, 0.6, -0.5], "intensity": [0.2, 0.3, 0.6], "group": "pair")" +
                  (pairOn ? "" : R"(, "on": false)") + "}";
    return R"({"lucerna": 1,
  "camera": {"position": [0, 3, 0.01], "target": [0, 0, 0], "fov_y": 50, "resolution": [24, 24]},
  "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}, "lamp": {"type": "emitter", "radiance": [1, 1, 1]}},
  "objects": [{"name": "floor", "material": "grey", "mesh": {"quad": [[-2, 0, -2], [-2, 0, 2], [2, 0, 2], [2, 0, -2]]}},
              {"name": "panel", "material": "lamp", "mesh": {"quad": [[1, 1.5, 1], [1.4, 1.5, 1], [1.4, 1.5, 1.4], [1, 1.5, 1.4]]}}],
  "lights": [)" + lights + "]}";
}

}  // namespace

class TestLightGroupRendering : public QObject {
    Q_OBJECT

private slots:
    // A light switched off renders exactly as the scene without it, and the file keeps it.
    void switchedOffLightsDoNotRender() {
        const SceneSnapshot off = sceneFromJson(litFloorJson(false));
        const SceneSnapshot without = sceneFromJson(litFloorJson(true, false));
        const SceneSnapshot on = sceneFromJson(litFloorJson(true));
        QCOMPARE(int(off->lights.size()), 3);
        QCOMPARE(int(withoutLightsSwitchedOff(off)->lights.size()), 1);
        QCOMPARE(withoutLightsSwitchedOff(on), on);  // all on: the same snapshot, no copy
        for (const char* backend : {"path", "bdpt"}) {
            const Image a = render(backend, off, 8, 3);
            const Image b = render(backend, without, 8, 3);
            const Image c = render(backend, on, 8, 3);
            double differs = 0, lit = 0;
            for (size_t i = 0; i < a.pixelCount(); ++i)
                for (int k = 0; k < 3; ++k) {
                    differs = std::max(differs, double(std::abs(a.pixels[i][k] - b.pixels[i][k])));
                    lit += c.pixels[i][k] - b.pixels[i][k];
                }
            QVERIFY2(differs == 0, backend);  // the same scene to the renderer: the same image
            QVERIFY2(lit > 0, backend);       // and switching the pair on adds its light
        }
        QCOMPARE(analyseFeatures(*off).pointLights, 1);
    }

    // Per-group layers: one layer for the pair (group.pair.*), one for the lone light and one for
    // the emitter; they add up to the image; switching the group off or scaling it whole re-mixes,
    // scaling one of its lights does not; past the limit of layers the render is refused.
    void groupLayersSumToTheImage() {
        const SceneSnapshot scene = sceneFromJson(litFloorJson(true));
        const std::vector<LightGroup> groups = lightGroups(*scene);
        QCOMPARE(int(groups.size()), 3);
        QCOMPARE(lightLayerChannel(groups[0], 'R'), std::string("light.solo.R"));
        QCOMPARE(lightLayerChannel(groups[1], 'G'), std::string("group.pair.G"));
        QCOMPARE(groups[1].members, (std::vector<int>{1, 2}));
        QCOMPARE(lightLayerChannel(groups[2], 'B'), std::string("emitter.panel.B"));
        QCOMPARE(int(sceneLitBy(*scene, groups[1]).lights.size()), 2);

        RenderSettings s;
        s.spp = 16;
        s.seed = 5;
        auto layered = makeLayeredBackend(findBackend("path")->make, scene, s);
        const RenderFrame frame = runBackend(*layered, "path", s);
        QVERIFY(frame.image.channels.count("group.pair.R") && frame.image.channels.count("light.solo.B"));
        QVERIFY(!frame.image.channels.count("light.p1.R"));
        Image summed = frame.image;
        mixLightLayers(summed, groups, {Rgb(1, 1, 1), Rgb(1, 1, 1), Rgb(1, 1, 1)});
        double pair = 0;
        for (size_t i = 0; i < summed.pixelCount(); ++i) {
            pair += frame.image.channels.at("group.pair.R")[i];
            for (int c = 0; c < 3; ++c)
                QVERIFY(std::abs(summed.pixels[i][c] - frame.image.pixels[i][c]) <= 1e-5f * (1 + frame.image.pixels[i][c]));
        }
        QVERIFY(pair > 0);

        Scene doubled = *scene, one = *scene, dark = *scene;
        for (int i : {1, 2}) doubled.lights[size_t(i)].intensity *= 2.0;
        one.lights[1].intensity *= 2.0;
        for (int i : {1, 2}) dark.lights[size_t(i)].on = false;
        const auto w = layerWeights(*scene, doubled);
        QVERIFY(w);
        QCOMPARE((*w)[1], Rgb(2, 2, 2));
        QCOMPARE((*w)[0], Rgb(1, 1, 1));
        QVERIFY(!layerWeights(*scene, one));  // the layer holds both lights: no one factor
        const auto off = layerWeights(*scene, dark);
        QVERIFY(off);
        QCOMPARE((*off)[1], Rgb(0, 0, 0));
        QVERIFY(!layerWeights(dark, *scene));  // the pair had no layer: switching it on restarts

        // 65 lights alone are 65 layers: refused in one line; in one group they are one layer.
        Scene many = *scene;
        many.lights.clear();
        for (int i = 0; i < 65; ++i) {
            Light l = scene->lights[0];
            l.name = "l" + std::to_string(i);
            many.lights.push_back(l);
        }
        try {
            makeLayeredBackend(findBackend("path")->make, std::make_shared<const Scene>(many), s);
            QFAIL("65 layers accepted");
        } catch (const std::invalid_argument& e) {
            QVERIFY(std::string(e.what()).find("more than 64") != std::string::npos);
            QVERIFY(std::string(e.what()).find('\n') == std::string::npos);
        }
        for (Light& l : many.lights) l.group = "all";
        QCOMPARE(int(lightGroups(many).size()), 2);  // the group and the emitter
    }
};

QTEST_GUILESS_MAIN(TestLightGroupRendering)
#include "test_light_group_rendering.moc"
