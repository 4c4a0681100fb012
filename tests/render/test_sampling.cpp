// Statistical and analytic tests of the warps (render/trace/warp.h), of an irradiance sensor's
// directions (render/trace/sensor.h) and of the chi-square harness itself
// (tests/support/chi_square.h). The materials' sampling: test_bsdf_sampling.
//
// Every statistical check draws from a fixed seed, so a run is deterministic; together they are
// held to a 1% chance of a false failure (tests/support/statistical_checks.h).

#include "render/trace/bsdf.h"
#include "render/trace/rng.h"
#include "render/trace/sensor.h"
#include "render/trace/warp.h"
#include "tests/support/chi_square.h"
#include "tests/support/statistical_checks.h"

#include <QtTest/QtTest>

#include <cmath>
#include <string>

using namespace lucerna;
using lucerna::test::direction;
using lucerna::test::logChi2;

namespace {

constexpr int kSamples = 1'000'000;

}  // namespace

class TestSampling : public QObject {
    Q_OBJECT

private slots:
    void cleanupTestCase() {
        QVERIFY2(checks_.countOk(), qPrintable(checks_.summary()));
        qInfo("%s", qPrintable(checks_.summary()));
    }

    // --- The harness itself -------------------------------------------------------------------

    void gammaFunction() {
        // Q(1, x) = exp(-x); Q(1/2, x) = erfc(sqrt(x)); chi-square dof 2: p = exp(-X^2 / 2).
        for (double x : {0.0, 0.1, 1.0, 3.0, 10.0, 50.0}) {
            QVERIFY(std::abs(regularizedGammaQ(1.0, x) - std::exp(-x)) <= 1e-12 + 1e-10 * std::exp(-x));
            QVERIFY(std::abs(regularizedGammaQ(0.5, x) - std::erfc(std::sqrt(x))) <=
                    1e-12 + 1e-9 * std::erfc(std::sqrt(x)));
        }
        QVERIFY(std::abs(chiSquarePValue(4.0, 2) - std::exp(-2.0)) < 1e-12);
        // Large dof: the statistic's mean is dof, so p(dof) is a little below 1/2.
        const double p = chiSquarePValue(1000.0, 1000);
        QVERIFY2(p > 0.45 && p < 0.5, qPrintable(QString::number(p)));
        QVERIFY(chiSquarePValue(2000.0, 1000) < 1e-30);
    }

    void harnessDetectsWrongPdf() {
        // Uniform hemisphere samples, claimed to be cosine-distributed: must fail, and hugely.
        const auto r = chiSquareSphere(
            [](Rng& rng, V3f& w) { w = squareToUniformHemisphere(rng.next2D()); return true; },
            [](const V3f& w) { return double(cosineHemispherePdf(w)); }, 20, 40, 100'000, checks_.nextSeed(),
            checks_.level());
        logChi2("wrong pdf (uniform sampled, cosine claimed)", r);
        QVERIFY2(!r.passed && r.pValue < 1e-12, r.message.c_str());
    }

    void harnessDetectsSubtlyWrongGgxPdf() {
        // VNDF samples against the pdf of sampling D(h) cos(theta_h): both are normalised
        // densities of h that differ only by the visibility weighting.
        const float alpha = 0.5f;
        const V3f wo = direction(60.0);
        const auto r = chiSquareSphere(
            [&](Rng& rng, V3f& h) { h = sampleGGXVisibleNormal(wo, alpha, rng.next2D()); return true; },
            [&](const V3f& h) { return double(ggxD(h, alpha)) * std::max(0.0f, h.z); }, 20, 40,
            kSamples, checks_.nextSeed(), checks_.level());
        logChi2("wrong GGX pdf (D cos claimed for VNDF samples)", r);
        QVERIFY2(!r.passed, r.message.c_str());
    }

    void harnessDetectsMissingFailures() {
        // A sampler that fails 2 % of the time behind a pdf that claims all the mass, and one
        // that never fails behind a pdf that claims 10 % failures: both must be caught.
        const auto a = chiSquareSphere(
            [](Rng& rng, V3f& w) {
                if (rng.next1D() < 0.02f) return false;
                w = squareToCosineHemisphere(rng.next2D());
                return true;
            },
            [](const V3f& w) { return double(cosineHemispherePdf(w)); }, 20, 40, 200'000,
            checks_.nextSeed(), checks_.level());
        logChi2("unaccounted failures", a);
        QVERIFY2(!a.passed, a.message.c_str());
        const auto b = chiSquareSphere(
            [](Rng& rng, V3f& w) { w = squareToCosineHemisphere(rng.next2D()); return true; },
            [](const V3f& w) { return 0.9 * cosineHemispherePdf(w); }, 20, 40, 200'000,
            checks_.nextSeed(), checks_.level());
        logChi2("missing failures", b);
        QVERIFY2(!b.passed, b.message.c_str());
    }

    // --- Warps --------------------------------------------------------------------------------

    void cosineHemisphere() {
        const auto r = chiSquareSphere(
            [](Rng& rng, V3f& w) { w = squareToCosineHemisphere(rng.next2D()); return true; },
            [](const V3f& w) { return double(cosineHemispherePdf(w)); }, 20, 40, kSamples,
            checks_.nextSeed(), checks_.significance());
        VERIFY_CHI2("cosine hemisphere", r);
        QVERIFY(std::abs(r.pdfIntegral - 1.0) < 1e-4);
    }

    // An irradiance sensor's block of pixels maps onto its hemisphere with density cos / pi
    // (render/trace/sensor.h), and rasterPoint() inverts the map.
    void irradianceSensorDirections() {
        const Sensor sensor({{V3f(0, 0, 0), V3f(0, 1, 0)}, {V3f(1, 2, 3), V3f(0.3f, -0.5f, 0.8f)}, {V3f(0, 0, 0), V3f(1, 0, 0)}}, 2);
        QCOMPARE(sensor.width(), 6);
        QCOMPARE(sensor.height(), 2);
        const auto r = chiSquareSphere(
            [&](Rng& rng, V3f& w) {
                const V2f u = rng.next2D();
                w = sensor.ray(2.0f + 2.0f * u.x, 2.0f * u.y).direction;
                return true;
            },
            [&](const V3f& w) { return double(sensor.pdfDirection(1, w)); }, 20, 40, kSamples, checks_.nextSeed(),
            checks_.significance());
        VERIFY_CHI2("irradiance sensor", r);
        QVERIFY(std::abs(r.pdfIntegral - 1.0) < 1e-4);

        Rng rng(7, 0);
        for (int i = 0; i < 1000; ++i) {
            const V2f u = rng.next2D();
            const float x = 2.0f + 2.0f * u.x, y = 2.0f * u.y;
            const Ray ray = sensor.ray(x, y);
            QCOMPARE(sensor.pointAt(x), 1);
            QVERIFY(ray.origin == V3f(1, 2, 3));
            float bx = 0, by = 0;
            QVERIFY(sensor.rasterPoint(1, ray.direction, bx, by));
            // phi wraps at v = 0 and 1; r^2 = u loses precision near the pole
            QVERIFY2(std::abs(bx - x) < 1e-3f && std::min(std::abs(by - y), 2.0f - std::abs(by - y)) < 1e-3f,
                     qPrintable(QString("(%1, %2) -> (%3, %4)").arg(x).arg(y).arg(bx).arg(by)));
        }
        float bx = 0, by = 0;  // the side behind the sensor is not measured
        QVERIFY(!sensor.rasterPoint(1, -sensor.normal(1), bx, by));
        QCOMPARE(sensor.pdfDirection(1, -sensor.normal(1)), 0.0f);
    }

    void uniformSphere() {
        const auto r = chiSquareSphere(
            [](Rng& rng, V3f& w) { w = squareToUniformSphere(rng.next2D()); return true; },
            [](const V3f&) { return double(uniformSpherePdf()); }, 20, 40, kSamples, checks_.nextSeed(),
            checks_.significance());
        VERIFY_CHI2("uniform sphere", r);
        QVERIFY(std::abs(r.pdfIntegral - 1.0) < 1e-4);
    }

    void uniformHemisphere() {
        const auto r = chiSquareSphere(
            [](Rng& rng, V3f& w) { w = squareToUniformHemisphere(rng.next2D()); return true; },
            [](const V3f& w) { return double(uniformHemispherePdf(w)); }, 20, 40, kSamples,
            checks_.nextSeed(), checks_.significance());
        VERIFY_CHI2("uniform hemisphere", r);
        QVERIFY(std::abs(r.pdfIntegral - 1.0) < 1e-4);
    }

    void uniformCone_data() {
        QTest::addColumn<double>("angleDeg");
        for (double a : {2.0, 10.0, 30.0, 90.0, 120.0})
            QTest::newRow(qPrintable(QString("%1 deg").arg(a))) << a;
    }
    void uniformCone() {
        QFETCH(double, angleDeg);
        const float cosMax = float(std::cos(angleDeg * std::numbers::pi / 180.0));
        const float pdfValue = uniformConePdf(cosMax);
        // Bin a cap a little wider than the cone, so the edge is resolved and visible.
        const double capDeg = std::min(180.0, angleDeg * 1.25);
        const auto r = chiSquareSphereCap(
            [&](Rng& rng, V3f& w) { w = squareToUniformCone(rng.next2D(), cosMax); return true; },
            [&](const V3f& w) { return w.z >= cosMax ? double(pdfValue) : 0.0; },
            std::cos(capDeg * std::numbers::pi / 180.0), 20, 40, kSamples, checks_.nextSeed(), checks_.significance());
        VERIFY_CHI2(qPrintable(QString("uniform cone %1 deg").arg(angleDeg)), r);
        QVERIFY(std::abs(r.pdfIntegral - 1.0) < 1e-3);
    }

    void uniformDisk() {
        const auto r = chiSquareRect(
            [](Rng& rng, V2f& p) { p = squareToUniformDisk(rng.next2D()); return true; },
            [](const V2f& p) { return p.x * p.x + p.y * p.y <= 1.0f ? double(uniformDiskPdf()) : 0.0; },
            V2f(-1, -1), V2f(1, 1), 40, 40, kSamples, checks_.nextSeed(), checks_.significance());
        VERIFY_CHI2("uniform disk", r);
        QVERIFY(std::abs(r.pdfIntegral - 1.0) < 1e-3);
    }

    void uniformTriangle() {
        const auto r = chiSquareRect(
            [](Rng& rng, V2f& b) { b = squareToUniformTriangle(rng.next2D()); return true; },
            [](const V2f& b) { return b.x >= 0 && b.y >= 0 && b.x + b.y <= 1.0f ? 2.0 : 0.0; },
            V2f(0, 0), V2f(1, 1), 40, 40, kSamples, checks_.nextSeed(), checks_.significance());
        VERIFY_CHI2("triangle barycentrics", r);
        QVERIFY(std::abs(r.pdfIntegral - 1.0) < 1e-3);
        // Every point is a valid barycentric pair, including at the corners of the square.
        for (V2f u : {V2f(0, 0), V2f(1, 1), V2f(0, 0.9999999f), V2f(0.9999999f, 0), V2f(0.5f, 0.5f)}) {
            const V2f b = squareToUniformTriangle(u);
            QVERIFY(b.x >= 0 && b.y >= 0 && b.x + b.y <= 1.0f);
        }
    }

private:
    lucerna::test::StatisticalChecks checks_{11, 20240611};
};

QTEST_APPLESS_MAIN(TestSampling)
#include "test_sampling.moc"
