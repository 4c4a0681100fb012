// The bundled office floor (issue 19, "real projects have many luminaires"): office_floor.json,
// 108 goniometric luminaires over an open-plan floor with furniture, and office_floor_points.json,
// the same geometry under isotropic point lights of equal flux that Blender Cycles can render
// (../shared/tools/cycles_ref.sh: point lights with `intensity` and OBJ meshes only). The scenes,
// meshes and photometric files are written by bench/make_office_floor.cpp; the references
// (office_floor*.ref.exr, 240 x 144) by bench/office_floor.sh (bench/office_floor.md).

#include "core/photometry/calculation_grid.h"
#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"
#include "core/photometry/luminaire.h"
#include "core/photometry/photometric_units.h"
#include "core/scene/scene_geometry.h"
#include "render/photometry/grid_calculation.h"
#include "render/trace/render_scene.h"
#include "render_helpers.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

using namespace lucerna;
using namespace lucerna::test;

namespace {

const std::string kScenes = std::string(LUCERNA_RESOURCE_DIR) + "/scenes/";

// The luminous flux of a light as the scene uses it (lm).
double fluxOf(const Light& light) {
    if (light.type == LightType::Luminaire) return luminaireFlux(light);
    return kLumensPerWatt * luminance(light.intensity) * pointSolidAngle();
}

}  // namespace

class TestOfficeFloor : public QObject {
    Q_OBJECT

private slots:
    // Many luminaires, and a point variant that differs in the lights alone.
    void scenesMatch() {
        const Scene lum = loadScene(kScenes + "office_floor.json");
        const Scene pts = loadScene(kScenes + "office_floor_points.json");
        int luminaires = 0;
        for (const Light& l : lum.lights) luminaires += l.type == LightType::Luminaire;
        QVERIFY2(luminaires >= 100, qPrintable(QString::number(luminaires)));
        QCOMPARE(int(lum.lights.size()), luminaires);
        QCOMPARE(pts.lights.size(), lum.lights.size());

        // Saved and read back unchanged (the loader's and the writer's view of the keys agree).
        for (const Scene* s : {&lum, &pts}) QVERIFY(parseScene(saveSceneToString(*s), kScenes + "x.json") == *s);

        QVERIFY(pts.camera == lum.camera);
        QVERIFY(pts.materials == lum.materials);
        QVERIFY(pts.objects == lum.objects);
        size_t triangles = 0;
        for (const Object& o : pts.objects) {
            // What cycles_ref.sh converts: OBJ files.
            QVERIFY2(o.mesh.kind == MeshSource::Kind::File && o.mesh.file.ends_with(".obj"), o.name.c_str());
            QVERIFY(!o.transform);
            triangles += o.worldMesh->triangles.size();
        }
        QVERIFY2(triangles > 3000, qPrintable(QString::number(triangles)));  // desks, screens, columns, ...

        for (size_t i = 0; i < lum.lights.size(); ++i) {
            const Light& a = lum.lights[i];
            const Light& b = pts.lights[i];
            QCOMPARE(b.name, a.name);
            QVERIFY(b.type == LightType::Point && !b.photometric);  // `intensity`, as Cycles reads it
            QCOMPARE(b.position.x, a.position.x);
            QCOMPARE(b.position.z, a.position.z);
            // Equal flux and colour, light by light.
            QVERIFY2(std::abs(fluxOf(b) / fluxOf(a) - 1) < 1e-5, a.name.c_str());
            const Rgbd colour = blackbodyColour(*a.luminaire->temperatureK);
            for (int c = 0; c < 3; ++c)
                QVERIFY(std::abs(b.intensity[c] / luminance(b.intensity) - colour[c]) < 1e-4);
        }
    }

    // The photometric files integrate to the flux they state (lucerna info warns beyond 2%); the
    // recessed panel sends nothing up, the pendant a fifth of its flux.
    void luminaireFiles() {
        const Scene lum = loadScene(kScenes + "office_floor.json");
        std::map<std::string, const GoniometricDistribution*> files;
        for (const Light& l : lum.lights) files[l.luminaire->file] = l.luminaire->distribution.get();
        QCOMPARE(int(files.size()), 2);
        const GoniometricDistribution* panel = files.at("luminaires/office_panel.ies");
        const GoniometricDistribution* linear = files.at("luminaires/office_linear.ldt");
        for (const GoniometricDistribution* d : {panel, linear})
            QVERIFY(std::abs(d->integratedFlux() / d->statedFluxLm - 1) < 0.005);
        QCOMPARE(panel->downwardFraction(), 1.0);
        QVERIFY(std::abs(linear->downwardFraction() - 0.8) < 0.005);
        // A batwing: the panel's peak lies off the nadir, the linear one's across its length.
        QVERIFY(panel->intensity(0, 30) > panel->intensity(0, 0));
        QVERIFY(linear->intensity(0, 35) > linear->intensity(90, 35));
    }

    // A short render's mean is the reference's (at 60 x 36 the mean of the image is still the
    // mean over the image plane: measured within 0.8% over 12 seeds), and its pixels the
    // reference's 4 x 4 blocks within the noise of 64 samples per pixel.
    void shortRenderAgainstReference_data() {
        QTest::addColumn<QString>("scene");
        // About twice the most of 12 seeds (luminaires: relmse 0.0074, block 4.3%; points: 0.0188, 7.0%).
        QTest::addColumn<double>("maxRelmse");
        QTest::addColumn<double>("maxBlockError");
        QTest::newRow("luminaires") << "office_floor" << 0.015 << 0.1;
        QTest::newRow("points") << "office_floor_points" << 0.04 << 0.15;
    }
    void shortRenderAgainstReference() {
        QFETCH(QString, scene);
        QFETCH(double, maxRelmse);
        QFETCH(double, maxBlockError);
        const std::string refPath = kScenes + scene.toStdString() + ".ref.exr";
        QVERIFY2(std::filesystem::is_regular_file(refPath), refPath.c_str());
        const Image reference = readExr(refPath);
        QCOMPARE(reference.width, 240);
        QCOMPARE(reference.height, 144);
        const SceneSnapshot snapshot = std::make_shared<const Scene>(loadScene(kScenes + scene.toStdString() + ".json"));
        RenderSettings settings;
        settings.spp = 64;
        settings.seed = 7;
        settings.width = 60;
        settings.height = 36;
        settings.options["light_sampler"] = "tree";
        const Image image = renderFrame("path", snapshot, settings).image;
        const ImageMetrics m = compareImages(image, reference.downsampled(4));
        qInfo("%s: mean %.5f against %.5f (%+.2f%%), relmse %.4f", qPrintable(scene), m.meanTest, m.meanRef,
              100 * (m.meanTest / m.meanRef - 1), m.relmse);
        QCOMPARE(m.nonfinite, 0L);
        QVERIFY(std::abs(m.meanTest / m.meanRef - 1) < 0.02);
        QVERIFY(m.relmse < maxRelmse);
        // Where the light falls: blocks of 12 x 12 pixels (5 x 3 of them) against the reference's.
        const Image blocks = image.downsampled(12), refBlocks = reference.downsampled(48);
        double worst = 0;
        for (size_t i = 0; i < blocks.pixels.size(); ++i)
            worst = std::max(worst, std::abs(double(luminance(blocks.pixels[i])) / luminance(refBlocks.pixels[i]) - 1));
        qInfo("worst block %.2f%%", 100 * worst);
        QVERIFY(worst < maxBlockError);
    }

    // An office's light level on the work plane (EN 12464-1, writing and reading: 500 lx, U0 at
    // least 0.6), on a coarse grid at 0.75 m to a 10% error target.
    void workPlaneIlluminance_data() {
        QTest::addColumn<QString>("scene");
        QTest::newRow("luminaires") << "office_floor";
        QTest::newRow("points") << "office_floor_points";
    }
    void workPlaneIlluminance() {
        QFETCH(QString, scene);
        const SceneSnapshot snapshot = std::make_shared<const Scene>(loadScene(kScenes + scene.toStdString() + ".json"));
        const SceneBounds b = sceneBounds(*snapshot);
        CalculationGrid grid = workPlaneGrid(b.lo, b.hi, snapshot->metersPerUnit, 0.75, 0.5);
        grid.spacingMeters = 6.0;
        const GridLayout layout = layoutGrid(grid, snapshot->metersPerUnit);
        GridSettings settings;
        settings.targetRelativeError = 0.1;
        settings.timeLimitSeconds = 30;
        const RenderScene renderScene(snapshot, 16, 16);
        TaskSystem tasks(0);
        GridResult result;
        auto job = tasks.submit([&](TaskContext& ctx) {
            result = computeGridIlluminance(renderScene, layout.points, grid.normal(), settings, ctx);
        });
        job->wait();
        job->rethrowIfFailed();
        const GridStatistics s = gridStatistics(result.lux, result.insideGeometry);
        qInfo("%s: %d points, Eavg %.0f lx, U0 %.2f, worst error %.1f%%", qPrintable(scene), s.counted, s.average,
              s.uniformity, 100 * result.maxRelativeError);
        QVERIFY(s.counted >= 20);
        QVERIFY2(s.average > 300 && s.average < 700, qPrintable(QString::number(s.average)));
        QVERIFY(s.uniformity > 0.6);
    }
};

QTEST_GUILESS_MAIN(TestOfficeFloor)
#include "test_office_floor.moc"
