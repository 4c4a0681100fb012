// The film's own error estimate (Film::estimatedRelmse) against true errors: films fed samples of
// a known image, light-tailed and with fireflies, and renders of scenes with and without
// fireflies against references; the estimate must agree with the expected true relmse within a
// factor of 1.5 (issue 25). The seeds' means are compared: one render's error is itself noisy.

#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"
#include "render_helpers.h"
#include "render/backend/film.h"

#include <QtTest>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

using namespace lucerna;

namespace {

// A known image with a smooth gradient and a sharp edge, as a render has both.
Image knownImage(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float v = (x < w / 2 ? 0.2f : 2.0f) * (1.0f + float(y) / h);
            img.pixels[size_t(y) * w + x] = {v, 0.5f * v, 0.25f * v};
        }
    return img;
}

struct Agreement {
    double estimated = 0, actual = 0;
    double ratio() const { return estimated / actual; }
};

// Feeds `passes` samples per pixel, alternating halves, each sample drawn by `sample(truth)`;
// means over `seeds` films.
template <typename Sampler>
Agreement filmAgreement(const Image& truth, int passes, int seeds, Sampler sample) {
    Agreement a;
    for (int seed = 0; seed < seeds; ++seed) {
        std::mt19937_64 rng(uint64_t(seed) * 7919 + 1);
        Film film(truth.width, truth.height);
        for (int p = 0; p < passes; ++p) {
            for (int y = 0; y < truth.height; ++y)
                for (int x = 0; x < truth.width; ++x) {
                    const auto& t = truth.pixels[size_t(y) * truth.width + x];
                    const double k = sample(rng);
                    film.addSample(p % 2, x, y, Rgb(float(t[0] * k), float(t[1] * k), float(t[2] * k)));
                }
            film.finishPass(p % 2);
        }
        a.estimated += film.estimatedRelmse() / seeds;
        a.actual += compareImages(film.image(), truth).relmse / seeds;
    }
    return a;
}

const std::string kSharedScenes = std::string(LUCERNA_SHARED_DIR) + "/scenes/";

std::string readResource(const std::string& name) {
    std::ifstream in(std::string(LUCERNA_RESOURCE_DIR) + "/scenes/" + name);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Renders of `backend` at `passes` over several seeds against `reference`.
Agreement renderAgreement(const std::string& backend, const SceneSnapshot& scene, const Image& reference, int passes,
                          int seeds, int w = 0, int h = 0) {
    Agreement a;
    for (int seed = 1; seed <= seeds; ++seed) {
        RenderSettings s;
        s.spp = passes;
        s.seed = uint64_t(seed);
        s.width = w;
        s.height = h;
        const RenderFrame f = test::renderFrame(backend, scene, s);
        a.estimated += f.estimatedRelmse / seeds;
        a.actual += compareImages(f.image, reference).relmse / seeds;
    }
    return a;
}

}  // namespace

class TestErrorEstimate : public QObject {
    Q_OBJECT
private slots:
    void lightTailedNoise() {
        // Samples uniform in [0.5, 1.5] times the pixel's value.
        const Agreement a = filmAgreement(knownImage(64, 48), 16, 4, [](std::mt19937_64& rng) {
            return 0.5 + std::uniform_real_distribution<double>(0, 1)(rng);
        });
        qInfo("light-tailed: estimated %.4g, actual %.4g", a.estimated, a.actual);
        QVERIFY2(a.ratio() > 1 / 1.5 && a.ratio() < 1.5, qPrintable(QString::number(a.ratio())));
    }

    void fireflies() {
        // Light-tailed noise carrying 80% of the light and, once in 400 samples, a firefly 80 times
        // the pixel's value carrying the rest: after 64 samples one pixel in six holds a firefly
        // that more than doubles it, as a path tracer's image of a room lit by many small lamps
        // does. The pixel's own mean would call such a pixel converged.
        const Agreement a = filmAgreement(knownImage(64, 48), 64, 4, [](std::mt19937_64& rng) {
            std::uniform_real_distribution<double> u(0, 1);
            return 0.8 * (0.5 + u(rng)) + (u(rng) < 1.0 / 400 ? 0.2 * 400 : 0.0);
        });
        qInfo("fireflies: estimated %.4g, actual %.4g", a.estimated, a.actual);
        QVERIFY(a.actual > 0.1);  // fireflies dominate: the light-tailed part alone gives 0.001
        QVERIFY2(a.ratio() > 1 / 1.5 && a.ratio() < 1.5, qPrintable(QString::number(a.ratio())));
    }

    void renderWithoutFireflies() {
        // The Cornell box by path tracing (an area light, diffuse walls, light-tailed noise) at its
        // own 256 x 256 against the reference of an independent renderer (Blender Cycles). At
        // 48 x 48 the estimate read 0.66 of the truth: the edges of the lamp, a few pixels wide,
        // dominate the error there, and 24 neighbours across such an edge are no stand-in for r.
        const auto scene = std::make_shared<const Scene>(loadScene(kSharedScenes + "cornell-box.json"));
        const Agreement a = renderAgreement("path", scene, readExr(kSharedScenes + "cornell-box.ref.exr"), 16, 4);
        qInfo("cornell path: estimated %.4g, actual %.4g", a.estimated, a.actual);
        QVERIFY2(a.ratio() > 1 / 1.5 && a.ratio() < 1.5, qPrintable(QString::number(a.ratio())));
    }

    void renderWithFireflies() {
        // The door scene by path tracing: a room lit through a door ajar, where a few paths find the
        // lamp and most do not. The estimate by the pixel's own mean was 6 times too low here.
        // The reference: the same backend with 32 times the work (its own error adds about 1/32).
        const auto scene = test::sceneFromJson(readResource("door.json"));
        const Image reference = test::render("path", scene, 32 * 32, 1000, 64, 48);
        const Agreement a = renderAgreement("path", scene, reference, 32, 4, 64, 48);
        qInfo("door path: estimated %.4g, actual %.4g", a.estimated, a.actual);
        QVERIFY(a.actual > 0.3);  // fireflies dominate
        QVERIFY2(a.ratio() > 1 / 1.5 && a.ratio() < 1.5, qPrintable(QString::number(a.ratio())));
    }
};

QTEST_GUILESS_MAIN(TestErrorEstimate)
#include "test_error_estimate.moc"
