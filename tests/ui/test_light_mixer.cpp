// The light mixer in the window: with per-light layers on, dimming, recolouring or switching off a
// light re-mixes the converged image at once and the render goes on (no restart); any other edit
// (a light moved) restarts it. Checks the frames' pixels against the layers they carry.

#include "closed_form_scenes.h"
#include "render/backend/light_layers/light_groups.h"
#include "ui/commands/light_commands.h"
#include "ui/rendering/converging_render.h"
#include "ui/window/main_window.h"
#include "window_test_helpers.h"

#include <QCheckBox>
#include <QComboBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace lucerna;
using namespace lucerna::test;

namespace {
constexpr int kTimeout = 60000;  // ms; generous for a loaded machine, never a timing assertion

double meanOf(const Image& image) {
    double sum = 0;
    for (const Rgb& p : image.pixels) sum += p.x + p.y + p.z;
    return sum / (3.0 * double(image.pixelCount()));
}
}  // namespace

class TestLightMixer : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        useTestSettings("test_light_mixer");
        QVERIFY(dir_.isValid());
    }

    void dimmingRemixesWithoutRestart() {
        RectangleOverPlane s;  // a square emitter over a floor, and a point light added under it
        std::string json = s.json();
        json.insert(json.size() - 1, R"(, "lights": [{"name": "bulb", "type": "point", "position": [0.3, 0.6, -0.2], "intensity": [0.5, 0.5, 0.5]}])");
        const QString path = dir_.filePath("mixer.json");
        std::ofstream(path.toStdString()) << json;
        MainWindow w(path);
        w.show();
        ConvergingRender* render = w.convergingRender();
        auto* backend = w.findChild<QComboBox*>("renderBackend");
        backend->setCurrentIndex(backend->findData("path"));
        auto* layers = w.findChild<QCheckBox*>("renderLightLayers");
        QVERIFY(layers);
        layers->setChecked(true);
        QVERIFY(render->lightLayers());
        QTest::mouseClick(w.findChild<QPushButton*>("renderStart"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(render->frame() && render->frame()->passes >= 8, kTimeout);

        const auto before = render->frame();
        const std::vector<LightGroup> groups = lightGroups(w.document()->scene());
        QCOMPARE(int(groups.size()), 2);
        QVERIFY(before->image.channels.count("light.bulb.R") && before->image.channels.count("emitter.lamp.G"));
        // Frames carry the albedo under each pixel (for the lux view) once the first pictures are out.
        QVERIFY(before->image.channels.count("albedo.R"));

        // The bulb three times brighter and without blue: a new mix, the same run.
        Light bulb = w.document()->scene().lights[0];
        bulb.intensity = Rgbd(1.5, 1.5, 0.0);
        w.document()->undoStack()->push(new EditLightCommand(w.document(), 0, bulb, 0, "dim"));
        const auto after = render->frame();
        QVERIFY(after);
        QCOMPARE(after->passes, before->passes);  // not restarted: the same passes, re-weighted
        Image expected = before->image;
        mixLightLayers(expected, groups, {Rgb(3, 3, 0), Rgb(1, 1, 1)});
        for (size_t i = 0; i < expected.pixelCount(); ++i)
            for (int c = 0; c < 3; ++c)
                QVERIFY(std::abs(after->image.pixels[i][c] - expected.pixels[i][c]) <= 1e-5f * (1 + expected.pixels[i][c]));
        QVERIFY(meanOf(after->image) > meanOf(before->image));

        // Later frames of the same run carry the mix too, and the passes go on.
        QTRY_VERIFY_WITH_TIMEOUT(render->frame()->passes > before->passes + 2, kTimeout);
        const auto later = render->frame();
        Image remixed = later->image;
        mixLightLayers(remixed, groups, {Rgb(3, 3, 0), Rgb(1, 1, 1)});
        QVERIFY(std::abs(meanOf(remixed) - meanOf(later->image)) <= 1e-5 * meanOf(later->image));

        w.grab().save("light_mixer.png");

        // Undo brings the old weights back, still without a restart.
        w.document()->undoStack()->undo();
        QVERIFY(render->frame()->passes >= later->passes);

        // Moving the light cannot be mixed: the render starts over.
        bulb = w.document()->scene().lights[0];
        bulb.position.x += 0.2;
        w.document()->undoStack()->push(new EditLightCommand(w.document(), 0, bulb, 0, "move"));
        QTRY_VERIFY_WITH_TIMEOUT(render->frame() && render->frame()->passes < later->passes, kTimeout);
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(TestLightMixer)
#include "test_light_mixer.moc"
