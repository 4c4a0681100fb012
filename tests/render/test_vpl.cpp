// VPL generation (render/vpl/) and the `ir` and `mir` backends: the power the particles bring,
// per-light generation, the contribution formula and its clamp, hard cases without a NaN, and
// consistency (4x the work at most halves relmse); mir's split of the VPL term from the rest, and
// its balance of Pc samples against the gather.

#include "closed_form_scenes.h"
#include "core/image/image_metrics.h"
#include "hard_case_scenes.h"
#include "render/progressive/mir/pc_balance.h"
#include "render/vpl/instant_radiosity.h"
#include "render/vpl/mir_path.h"
#include "render/vpl/vpl_contribution.h"
#include "render/vpl/vpl_gatherer.h"
#include "render_helpers.h"

#include <QtTest>

using namespace lucerna;
using namespace lucerna::test;

namespace {

RenderScene makeRenderScene(const std::string& json) { return RenderScene(sceneFromJson(json)); }

double sumLuminance(const VplSet& vpls, int bounce = 0) {
    double s = 0;
    for (const Vpl& v : vpls)
        if (bounce == 0 || v.bounce == bounce) s += luminance(v.power);
    return s;
}

// A coarse closed sphere of albedo rho (12 rings of 24 segments) seen at 8x8 pixels.
SphereWithEmittingCap smallSphere(double rho) {
    SphereWithEmittingCap s;
    s.rho = rho;
    s.rings = 12;
    s.segments = 24;
    s.resolution = 8;
    return s;
}

// Two lamps over the floor of RectangleOverPlane: one emissive quad and a point light.
std::string twoLightScene() {
    RectangleOverPlane r;
    std::string json = r.json();
    json.pop_back();  // the closing brace
    return json + R"(, "lights": [{"name": "bulb", "type": "point", "position": [0, 2, 0], "intensity": [3, 3, 3]}]})";
}

}  // namespace

class TestVpl : public QObject {
    Q_OBJECT
private slots:
    void firstBounceCarriesIncidentFlux();
    void perLightSetsConcatenate();
    void contributionFormulaAndClamp();
    void radiancePartsSumToRadiance();
    void pcBalanceIsTheLeastError();
    void pcSamplesEstimateTheChainsMean();
    void hardCases_data();
    void hardCases();
    void consistency_data();
    void consistency();
    void residualCarriesWhatTheClampTakes_data();
    void residualCarriesWhatTheClampTakes();
};

void TestVpl::firstBounceCarriesIncidentFlux() {
    // Every particle of the 1x1 emitter (radiance 2, flux 2 pi) lands on the 40x40 floor below
    // it but for the form factor to the floor's outside, under 1e-3: bounce-1 VPL powers sum to
    // the emitted flux; the floor's albedo 0.5 then halves what bounce 2 could carry (it has no
    // second surface: there are none).
    RectangleOverPlane s;
    const RenderScene scene = makeRenderScene(s.json());
    const VplSet vpls = generateVpls(scene, 20000, 3);
    const double flux = std::numbers::pi * s.radiance * (2 * s.a) * (2 * s.a);  // pi L A, one-sided
    const double first = sumLuminance(vpls, 1);
    qInfo("bounce-1 power %.5f, emitted flux %.5f, VPLs %zu", first, flux, vpls.size());
    QVERIFY(std::abs(first / flux - 1.0) < 0.005);
    QCOMPARE(sumLuminance(vpls), first);  // nothing above the floor to bounce off
    for (const Vpl& v : vpls) {
        QVERIFY(isFinite(v.power));
        QVERIFY(v.normal.y > 0.99f);  // turned toward the side the light came from
        QVERIFY(v.incident.y > 0.0f);
    }
    VplOptions o;
    o.minBounce = 2;
    QVERIFY(generateVpls(scene, 2000, 3, o).empty());
}

void TestVpl::perLightSetsConcatenate() {
    const RenderScene scene = makeRenderScene(twoLightScene());
    const auto sources = vplLightSources(scene);
    QCOMPARE(sources.size(), size_t(2));
    QCOMPARE(sources[0].name, std::string("lamp"));
    QVERIFY(sources[0].isObject);
    QCOMPARE(sources[1].name, std::string("bulb"));
    QVERIFY(!sources[1].isObject);
    // The expected flux reaching the floor, per source, from the all-lights set; and from the
    // per-light sets generated with very different path counts: the sums agree.
    // (The bulb's particles hit the floor with probability 0.39: 200000 of them give its sum to
    // 0.3%, one standard deviation.)
    const double all = sumLuminance(generateVpls(scene, 400000, 5));
    const double lamp = sumLuminance(generateVplsForLight(scene, 0, 20000, 6));
    const double bulb = sumLuminance(generateVplsForLight(scene, 1, 200000, 7));
    qInfo("all %.4f, lamp %.4f + bulb %.4f = %.4f", all, lamp, bulb, lamp + bulb);
    QVERIFY(std::abs((lamp + bulb) / all - 1.0) < 0.01);
    // The bulb is isotropic (3 W/sr, at height 2); the floor gets I times the solid angle of its
    // 40x40 quad less that of the lamp's 1x1 quad (height 1) in the way, whose back reflects
    // nothing. Solid angle of a square of half-size a at distance h: 4 asin(a^2 / (a^2 + h^2)).
    const auto squareSolidAngle = [](double a, double h) { return 4 * std::asin(a * a / (a * a + h * h)); };
    const double omega = squareSolidAngle(20, 2) - squareSolidAngle(0.5, 1);
    qInfo("bulb onto the floor %.4f, closed form %.4f", bulb, 3.0 * omega);
    QVERIFY(std::abs(bulb / (3.0 * omega) - 1.0) < 0.01);
    QVERIFY(generateVplsForLight(scene, 2, 100, 1).empty());
}

void TestVpl::contributionFormulaAndClamp() {
    RectangleOverPlane s;
    const RenderScene scene = makeRenderScene(s.json());
    Vpl v;
    v.position = V3f(0, 0, 0);
    v.pError = V3f(1e-6f);
    v.normal = V3f(0, 1, 0);
    v.incident = V3f(0, 1, 0);
    v.power = Rgb(2, 2, 2);
    v.material = 0;  // "floor", the first material
    // A receiver facing down at height d: L = rho/pi * P * rho/pi * 1 / d^2 (both cosines 1).
    const ShadingMaterial& floor = scene.material(v.material);
    QCOMPARE(floor.type, MaterialType::Diffuse);
    for (float d : {0.1f, 0.5f, 2.0f}) {
        SurfacePoint x;
        x.p = V3f(0, d, 0);
        x.pError = V3f(1e-6f);
        x.ng = V3f(0, -1, 0);
        const VplReceiver r{x, &floor, V3f(0, -1, 0)};
        const double expected = (s.rho / std::numbers::pi) * 2.0 * (s.rho / std::numbers::pi) / (d * d);
        const Rgb c = vplContributionUnshadowed(scene, v, r, kNoClamp);
        QVERIFY(std::abs(c.x / expected - 1.0) < 1e-5);
        const float bound = 4.0f;  // G clamped to 4: d < 0.5 is clamped
        const Rgb clamped = vplContributionUnshadowed(scene, v, r, bound);
        const double expectedClamped = expected * std::min(1.0, bound * double(d) * d);
        QVERIFY(std::abs(clamped.x / expectedClamped - 1.0) < 1e-5);
        // The receiver's back side gets nothing.
        const VplReceiver back{x, &floor, V3f(0, 1, 0)};
        QVERIFY(isBlack(vplContributionUnshadowed(scene, v, back, kNoClamp)));
    }
    // The clamp bound scales with the scene: the same fraction of the radius everywhere.
    QVERIFY(std::abs(geometricClampBound(scene, 0.1f) * std::pow(0.1f * scene.boundsRadius(), 2.0f) - 1.0f) < 1e-5f);
    QVERIFY(std::isinf(geometricClampBound(scene, 0.0f)));
}

void TestVpl::radiancePartsSumToRadiance() {
    // mir keeps the VPL term in a film of its own, scaled by the newest Pc when read: the parts
    // must be radiance() split, drawing the same numbers, and the VPL part linear in the powers.
    // The clamp takes part of every bounce here (as in residualCarriesWhatTheClampTakes), so the
    // residual's VPL term at x2 is in the VPL part too.
    SphereWithEmittingCap s = smallSphere(0.5);
    const RenderScene scene = makeRenderScene(s.json());
    VplSet vpls = generateVpls(scene, 200, 5);
    QVERIFY(vpls.size() > 50);
    GatherSettings clamping;
    clamping.clampFraction = 4;
    clamping.residualVplShare = 0.5f;
    const VplGatherer gatherer(scene, clamping);
    VplSet doubled = vpls;
    for (Vpl& v : doubled) v.power *= 2.0f;
    int withVplLight = 0;
    for (int y = 0; y < s.resolution; ++y)
        for (int x = 0; x < s.resolution; ++x) {
            const Ray ray = scene.camera().ray(float(x) + 0.5f, float(y) + 0.5f);
            Rng a(7, uint64_t(y * s.resolution + x)), b = a, c = a;
            const Rgb whole = gatherer.radiance(ray, a, vpls);
            const VplGatherer::Parts parts = gatherer.radianceParts(ray, b, vpls);
            const VplGatherer::Parts twice = gatherer.radianceParts(ray, c, doubled);
            const Rgb sum = parts.rest + parts.vpl;
            for (int k = 0; k < 3; ++k) {
                QVERIFY(std::abs(sum[k] - whole[k]) <= 1e-5f * std::max(1.0f, std::abs(whole[k])));
                QVERIFY(std::abs(twice.vpl[k] - 2.0f * parts.vpl[k]) <= 1e-5f * std::max(1.0f, parts.vpl[k]));
                QCOMPARE(twice.rest[k], parts.rest[k]);
            }
            QCOMPARE(a.next1D(), b.next1D());  // the same numbers drawn
            if (luminance(parts.vpl) > 0) ++withVplLight;
        }
    QVERIFY(withVplLight > s.resolution * s.resolution / 2);
}

void TestVpl::pcBalanceIsTheLeastError() {
    // The error at a fixed cost, (s rho / m + B) (c_g + c_pc m), is least at the m returned.
    PcBalance b;
    b.sensitivity = 0.7;
    b.sampleRelativeVariance = 0.9;
    b.passRelmse = 6e-5;
    b.passRays = 5e5;
    b.sampleRays = 50;
    const auto error = [&](double m) { return (b.sensitivity * b.sampleRelativeVariance / m + b.passRelmse) * (b.passRays + b.sampleRays * m); };
    const int m = balancedPcSamples(b, 1, 1 << 30, 1000);
    qInfo("balanced Pc samples a pass: %d", m);
    QVERIFY(m > 100 && m < 1000000);
    QVERIFY(error(m) <= error(m * 1.2) && error(m) <= error(m / 1.2));
    // Twice the gather's error, a sqrt(2) fewer Pc samples; the bounds hold; a missing measure
    // keeps the fallback.
    b.passRelmse *= 2;
    QVERIFY(std::abs(balancedPcSamples(b, 1, 1 << 30, 1000) * std::sqrt(2.0) / m - 1.0) < 0.01);
    QCOMPARE(balancedPcSamples(b, 1, 100, 1000), 100);
    QCOMPARE(balancedPcSamples(b, 100000, 200000, 1000), 100000);
    b.passRelmse = 0;
    QCOMPARE(balancedPcSamples(b, 1, 1 << 30, 1000), 1000);
    b.passRelmse = std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(balancedPcSamples(b, 1, 1 << 30, 1000), 1000);
}

void TestVpl::pcSamplesEstimateTheChainsMean() {
    // Pc is the mean of the chain's f(u) at uniform u, its paths ended by the chain's roulette;
    // the cheap samples play their own and weigh each vertex's floor by the chain's reach. Their
    // mean must be the chain's: with a floor twice a vertex's mean importance, a floor counted
    // per vertex reached (not weighted) moved it by 31% (the bound: 2.7%). And in a closed sphere
    // of albedo 0.9, where the chain's path lengths are most of f's spread, they vary less (0.38
    // against 0.86).
    SphereWithEmittingCap s = smallSphere(0.9);
    const RenderScene scene = makeRenderScene(s.json());
    const auto points = traceImportancePoints(scene, scene.camera(), 16, 16, 3);
    QCOMPARE(points.size(), size_t(16));
    const VplOptions options;
    const float maxG = geometricClampBound(scene, 0.1f);
    const auto meanAndRelativeVariance = [](const std::vector<double>& f) {
        double sum = 0, squares = 0;
        for (double x : f) sum += x, squares += x * x;
        const double n = double(f.size()), mean = sum / n;
        return std::pair{mean, (squares / n - mean * mean) / (mean * mean)};
    };
    Rng rng(11, 0);
    std::vector<float> u(size_t(mirPathDimension(options)));
    MirPath path;
    std::vector<double> importance, chain, cheap;
    long long vertices = 0;
    for (int i = 0; i < 2000; ++i) {
        for (float& x : u) x = rng.next1D();
        importance.push_back(evaluateMirLightPath(scene, scene.lights(), points, options, maxG, 0.0, u, path));
        vertices += (long long)path.vpls.size();
    }
    const double floor = 2.0 * meanAndRelativeVariance(importance).first * 2000.0 / double(vertices);
    for (int i = 0; i < 24000; ++i) {
        for (float& x : u) x = rng.next1D();
        chain.push_back(evaluateMirLightPath(scene, scene.lights(), points, options, maxG, floor, u, path));
    }
    for (int i = 0; i < 40000; ++i)
        cheap.push_back(estimateMirImportance(scene, scene.lights(), points, options, maxG, floor, 4, rng));
    const auto [chainMean, chainVariance] = meanAndRelativeVariance(chain);
    const auto [cheapMean, cheapVariance] = meanAndRelativeVariance(cheap);
    const double sigma = std::sqrt(chainVariance / double(chain.size()) + cheapVariance / double(cheap.size()));
    qInfo("Pc: chain %.5f (relative variance %.3f), cheap samples %.5f (%.3f), relative difference %.4f, sigma %.4f",
          chainMean, chainVariance, cheapMean, cheapVariance, cheapMean / chainMean - 1.0, sigma);
    QVERIFY(std::abs(cheapMean / chainMean - 1.0) < 4.0 * sigma);
    QVERIFY(sigma < 0.02);
    QVERIFY(cheapVariance < 0.7 * chainVariance);
}

void TestVpl::hardCases_data() {
    QTest::addColumn<QString>("backend");
    QTest::addColumn<QString>("scene");
    for (const char* backend : {"ir", "mir"})
        for (const HardCase& c : hardCaseScenes())
            QTest::newRow(qPrintable(QString("%1 %2").arg(backend, QString::fromStdString(c.name))))
                << backend << QString::fromStdString(c.json);
}

void TestVpl::hardCases() {
    QFETCH(QString, backend);
    QFETCH(QString, scene);
    const Image img = render(backend.toStdString(), sceneFromJson(scene.toStdString()), 4, 9);
    long nonfinite = 0;
    for (const Rgb& p : img.pixels)
        if (!isFinite(p)) ++nonfinite;
    QCOMPARE(nonfinite, 0L);
}

void TestVpl::consistency_data() {
    QTest::addColumn<QString>("backend");
    QTest::newRow("ir") << "ir";
    QTest::newRow("mir") << "mir";
}

void TestVpl::consistency() {
    // The sphere with an emitting cap (uniform radiance, known in closed form), small: relmse of
    // 4x the passes is at most half that of 1x (an unbiased or consistent method gives a quarter;
    // a biased one stalls at its bias).
    QFETCH(QString, backend);
    SphereWithEmittingCap s;
    s.rho = 0.8;
    s.resolution = 16;
    const auto scene = sceneFromJson(s.json());
    const double expected = s.expectedRadiance();
    Image ref;
    ref.width = ref.height = s.resolution;
    ref.pixels.assign(size_t(s.resolution) * s.resolution, Rgb(float(expected)));
    double relmse[2], means[2] = {0, 0};
    const int spp[2] = {8, 32};
    for (int i = 0; i < 2; ++i) {
        double sum = 0;
        const int seeds = 3;  // averaged over seeds: one run's relmse is itself noisy
        for (int k = 0; k < seeds; ++k) {
            RenderSettings rs;
            rs.spp = spp[i];
            rs.seed = 100 + k;
            // ir's default 32 particles per pass make each pass's image error one heavy-tailed
            // draw shared by every pixel; 3 seeds of 8 passes cannot average that. 512 can.
            if (backend == "ir") rs.options["vpl_paths"] = "512";
            const Image img = renderFrame(backend.toStdString(), scene, rs).image;
            means[i] += img.mean() / expected / seeds;
            sum += compareImages(img, ref).relmse;
        }
        relmse[i] = sum / seeds;
    }
    qInfo("%s: relmse %.3g at %d spp, %.3g at %d spp (ratio %.3f); mean / closed form %.4f, %.4f", qPrintable(backend),
          relmse[0], spp[0], relmse[1], spp[1], relmse[1] / relmse[0], means[0], means[1]);
    QVERIFY(relmse[1] <= 0.5 * relmse[0]);
}

void TestVpl::residualCarriesWhatTheClampTakes_data() {
    QTest::addColumn<QString>("backend");
    QTest::addColumn<QString>("share");  // of the residual estimated by the VPLs at x2
    QTest::newRow("ir, by paths") << "ir" << "0";
    QTest::newRow("ir, by VPLs") << "ir" << "1";
    QTest::newRow("mir, by both") << "mir" << "0.5";
}

void TestVpl::residualCarriesWhatTheClampTakes() {
    // In a sphere every pair of points has G = 1 / (4 R^2); a clamp distance of four times the
    // scene's radius clamps G to at most a quarter of that, so the residual carries at least
    // three quarters of every indirect bounce. The mean must still be the closed form's, and
    // without the residual far below it (the check can fail).
    QFETCH(QString, backend);
    QFETCH(QString, share);
    SphereWithEmittingCap s;
    s.rho = 0.8;
    s.rings = 24;
    s.segments = 48;
    s.resolution = 16;
    const auto scene = sceneFromJson(s.json());
    const double expected = s.expectedRadiance();
    const auto mean = [&](bool compensate, int spp) {
        RenderSettings rs;
        rs.spp = spp;
        rs.seed = 7;
        rs.options["clamp"] = "4";
        rs.options["compensate"] = compensate ? "1" : "0";
        rs.options["residual_vpls"] = share.toStdString();
        if (backend == "ir") rs.options["vpl_paths"] = "256";
        return renderFrame(backend.toStdString(), scene, rs).image.mean() / expected;
    };
    const double compensated = mean(true, 32), clamped = mean(false, 4);
    qInfo("%s, share %s: mean / closed form %.4f (without the residual %.4f)", qPrintable(backend), qPrintable(share),
          compensated, clamped);
    QVERIFY(std::abs(compensated - 1.0) < 0.015);
    QVERIFY(clamped < 0.8);
}

QTEST_GUILESS_MAIN(TestVpl)
#include "test_vpl.moc"
