// Statistical and analytic tests of the SPEC materials (render/trace/bsdf.h): GGX's visible
// normals, each material's sampling against its pdf (chi-square), eval against SPEC's formulas,
// reciprocity, the white furnace, and the dielectric's Fresnel choice. The warps: test_sampling.
//
// Every statistical check draws from a fixed seed, so a run is deterministic; together they are
// held to a 1% chance of a false failure (tests/support/statistical_checks.h). The seeds go on
// from those test_sampling's checks used when the two were one executable.

#include "render/trace/bsdf.h"
#include "render/trace/rng.h"
#include "render/trace/warp.h"
#include "tests/support/chi_square.h"
#include "tests/support/statistical_checks.h"

#include <QtTest/QtTest>

#include <cmath>
#include <string>

using namespace lucerna;
using lucerna::test::direction;

namespace {

constexpr int kSamples = 1'000'000;

ShadingMaterial glossy(float albedo, float specular, float alpha) {
    Material m;
    m.type = MaterialType::Glossy;
    m.albedo = Rgbd(albedo, albedo, albedo);
    m.specular = Rgbd(specular, specular, specular);
    m.roughness = alpha;
    return ShadingMaterial::fromMaterial(m);
}

ShadingMaterial diffuse(float albedo) {
    Material m;
    m.type = MaterialType::Diffuse;
    m.albedo = Rgbd(albedo, albedo, albedo);
    return ShadingMaterial::fromMaterial(m);
}

ShadingMaterial dielectric(float ior) {
    Material m;
    m.type = MaterialType::Dielectric;
    m.ior = ior;
    return ShadingMaterial::fromMaterial(m);
}

// SPEC glossy f, written literally in double (an independent implementation to compare with).
double specGlossy(double albedo, double specular, double alpha, const V3f& wo, const V3f& wi) {
    if (wo.z <= 0 || wi.z <= 0) return 0.0;
    const double hx = double(wo.x) + wi.x, hy = double(wo.y) + wi.y, hz = double(wo.z) + wi.z;
    const double hl = std::sqrt(hx * hx + hy * hy + hz * hz);
    const double nh = hz / hl, a2 = alpha * alpha;
    const double q = nh * nh * (a2 - 1.0) + 1.0;
    const double d = a2 / (std::numbers::pi * q * q);
    auto g1 = [&](double c) {
        const double tan2 = (1.0 - c * c) / (c * c);
        return 2.0 / (1.0 + std::sqrt(1.0 + a2 * tan2));
    };
    return albedo / std::numbers::pi + specular * d * g1(wi.z) * g1(wo.z) / (4.0 * wi.z * wo.z);
}

// Fresnel from the Snell angles (sin/tan form), independent of the cosine form under test.
double fresnelBySines(double cosI, double n1, double n2) {
    const double ti = std::acos(cosI);
    const double sinT = n1 / n2 * std::sin(ti);
    if (sinT >= 1.0) return 1.0;
    const double tt = std::asin(sinT);
    if (ti == 0.0) {
        const double r = (n1 - n2) / (n1 + n2);
        return r * r;
    }
    const double rs = std::sin(ti - tt) / std::sin(ti + tt);
    const double rp = std::tan(ti - tt) / std::tan(ti + tt);
    return 0.5 * (rs * rs + rp * rp);
}

bool finite(const V3f& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

class TestBsdfSampling : public QObject {
    Q_OBJECT

private slots:
    void cleanupTestCase() {
        QVERIFY2(checks_.countOk(), qPrintable(checks_.summary()));
        qInfo("%s", qPrintable(checks_.summary()));
    }

    // --- GGX ----------------------------------------------------------------------------------

    void ggxMatchesSpec() {
        Rng rng(7);
        for (float alpha : {0.05f, 0.2f, 0.7f, 1.0f}) {
            for (int i = 0; i < 2000; ++i) {
                const V3f h = squareToUniformHemisphere(rng.next2D());
                if (h.z <= 1e-3f) continue;
                const double a2 = double(alpha) * alpha, c = h.z;
                const double q = c * c * (a2 - 1.0) + 1.0;
                const double d = a2 / (std::numbers::pi * q * q);
                QVERIFY2(std::abs(ggxD(h, alpha) - d) <= 1e-4 * d, qPrintable(QString("D %1 vs %2").arg(ggxD(h, alpha)).arg(d)));
                const double tan2 = (1.0 - c * c) / (c * c);
                const double g1 = 2.0 / (1.0 + std::sqrt(1.0 + a2 * tan2));
                QVERIFY(std::abs(smithG1(h, alpha) - g1) <= 1e-5);
            }
            QCOMPARE(smithG1(V3f(1, 0, 0), alpha), 0.0f);
            QCOMPARE(smithG1(V3f(0, 0, 1), alpha), 1.0f);
            QVERIFY(std::abs(smithG1OverCos(V3f(1, 0, 0), alpha) - 2.0f / alpha) < 1e-4f / alpha);
            // D is a distribution of normals: its projected integral is 1.
            const double projected = integrateOverSphere(
                [&](const V3f& h) { return double(ggxD(h, alpha)) * std::max(0.0f, h.z); });
            QVERIFY2(std::abs(projected - 1.0) < 1e-4, qPrintable(QString::number(projected, 'g', 10)));
        }
    }

    void ggxVisibleNormals_data() {
        QTest::addColumn<float>("alpha");
        QTest::addColumn<double>("thetaDeg");
        for (float alpha : {0.05f, 0.2f, 0.5f, 1.0f})
            for (double t : {0.0, 45.0, 80.0, 90.0})
                QTest::newRow(qPrintable(QString("alpha %1, wo %2 deg").arg(alpha).arg(t))) << alpha << t;
    }
    void ggxVisibleNormals() {
        QFETCH(float, alpha);
        QFETCH(double, thetaDeg);
        // 90 degrees exactly on the horizon (the float cosine of pi/2 is not 0).
        const V3f wo = thetaDeg == 90.0 ? V3f(1, 0, 0) : direction(thetaDeg, 30.0);
        const double capRad = std::min(std::numbers::pi, 12.0 * alpha);
        const auto r = chiSquareSphereCap(
            [&](Rng& rng, V3f& h) { h = sampleGGXVisibleNormal(wo, alpha, rng.next2D()); return true; },
            [&](const V3f& h) { return double(ggxVisibleNormalPdf(wo, h, alpha)); },
            std::cos(capRad), 20, 40, kSamples, checks_.nextSeed(), checks_.significance());
        VERIFY_CHI2(QTest::currentDataTag(), r);
        // Exact Smith G1 of this D: the visible normal density is normalised.
        QVERIFY2(std::abs(r.pdfIntegral - 1.0) < 1e-3, qPrintable(QString::number(r.pdfIntegral, 'g', 8)));
    }

    // --- BSDF sampling against bsdfPdf ---------------------------------------------------------

    void diffuseSampling_data() {
        QTest::addColumn<double>("thetaDeg");
        for (double t : {0.0, 60.0, 89.0}) QTest::newRow(qPrintable(QString("wo %1 deg").arg(t))) << t;
    }
    void diffuseSampling() {
        QFETCH(double, thetaDeg);
        const ShadingMaterial m = diffuse(0.8f);
        const V3f wo = direction(thetaDeg, 10.0);
        const auto r = chiSquareSphere(
            [&](Rng& rng, V3f& w) {
                BsdfSample s;
                if (!bsdfSample(m, wo, rng.next2D(), rng.next1D(), s)) return false;
                w = s.wi;
                return true;
            },
            [&](const V3f& w) { return double(bsdfPdf(m, wo, w)); }, 20, 40, kSamples, checks_.nextSeed(),
            checks_.significance());
        VERIFY_CHI2(QTest::currentDataTag(), r);
        QVERIFY(std::abs(r.pdfIntegral - 1.0) < 1e-4);
    }

    void glossySampling_data() {
        QTest::addColumn<float>("albedo");
        QTest::addColumn<float>("specular");
        QTest::addColumn<float>("alpha");
        QTest::addColumn<double>("thetaDeg");
        for (float alpha : {0.05f, 0.1f, 0.3f, 0.6f, 1.0f})
            for (double t : {0.0, 50.0, 85.0})
                QTest::newRow(qPrintable(QString("mixture, alpha %1, wo %2 deg").arg(alpha).arg(t)))
                    << 0.3f << 0.6f << alpha << t;
        // Pure specular (diffuseLobeProb 0), including the narrowest lobe near grazing.
        QTest::newRow("specular only, alpha 0.05, wo 85 deg") << 0.0f << 0.9f << 0.05f << 85.0;
        QTest::newRow("specular only, alpha 0.3, wo 60 deg") << 0.0f << 0.9f << 0.3f << 60.0;
        QTest::newRow("specular only, alpha 0.05, wo 89.9 deg") << 0.0f << 0.9f << 0.05f << 89.9;
        // Diffuse-heavy mixture: lobe probability clamped at 0.9.
        QTest::newRow("diffuse-heavy, alpha 0.1, wo 30 deg") << 0.9f << 0.02f << 0.1f << 30.0;
    }
    void glossySampling() {
        QFETCH(float, albedo);
        QFETCH(float, specular);
        QFETCH(float, alpha);
        QFETCH(double, thetaDeg);
        const ShadingMaterial m = glossy(albedo, specular, alpha);
        const V3f wo = direction(thetaDeg, -70.0);
        auto sample = [&](Rng& rng, V3f& w) {
            BsdfSample s;
            if (!bsdfSample(m, wo, rng.next2D(), rng.next1D(), s)) return false;
            w = s.wi;
            return true;
        };
        auto pdf = [&](const V3f& w) { return double(bsdfPdf(m, wo, w)); };
        // A narrow lobe around the normal falls into one or two equal-cos cells of the whole
        // sphere: bin a cap around it instead (the rest is one category).
        const bool narrowAtPole = alpha <= 0.1f && thetaDeg < 10.0;
        const auto r = narrowAtPole
                           ? chiSquareSphereCap(sample, pdf, std::cos(0.6), 20, 40, kSamples, checks_.nextSeed(), checks_.significance())
                           : chiSquareSphere(sample, pdf, 40, 80, kSamples, checks_.nextSeed(), checks_.significance());
        VERIFY_CHI2(QTest::currentDataTag(), r);
        QVERIFY2(r.pdfIntegral <= 1.0 + 1e-3, qPrintable(QString::number(r.pdfIntegral)));
    }

    // --- Consistency, reciprocity, energy -----------------------------------------------------

    void weightIsEvalCosOverPdf() {
        Rng rng(11);
        const ShadingMaterial materials[] = {diffuse(0.7f),        glossy(0.3f, 0.6f, 0.05f),
                                             glossy(0.3f, 0.6f, 0.5f), glossy(0.0f, 1.0f, 0.2f),
                                             glossy(0.5f, 0.0f, 0.3f), glossy(0.0f, 1.0f, kMinGgxAlpha)};
        int checked = 0;
        for (const ShadingMaterial& m : materials) {
            for (int i = 0; i < 20000; ++i) {
                const V3f wo = squareToUniformHemisphere(rng.next2D());
                BsdfSample s;
                if (!bsdfSample(m, wo, rng.next2D(), rng.next1D(), s)) continue;
                QVERIFY(!s.isDelta && !s.refracted);
                QVERIFY(finite(s.wi) && std::abs(s.wi.length() - 1.0f) < 1e-5f && s.wi.z > 0);
                const float pdf = bsdfPdf(m, wo, s.wi);
                QVERIFY2(pdf > 0 && std::abs(s.pdf - pdf) <= 1e-6f * pdf, "sample pdf != bsdfPdf");
                const Rgb expected = bsdfEval(m, wo, s.wi) * (s.wi.z / pdf);
                for (int c = 0; c < 3; ++c) {
                    QVERIFY(std::isfinite(s.weight[c]) && s.weight[c] >= 0);
                    QVERIFY2(std::abs(s.weight[c] - expected[c]) <= 1e-5f * std::max(1.0f, expected[c]),
                             qPrintable(QString("weight %1 vs eval*cos/pdf %2").arg(s.weight[c]).arg(expected[c])));
                }
                ++checked;
            }
        }
        QVERIFY(checked > 100000);
    }

    void reciprocity() {
        Rng rng(13);
        const ShadingMaterial materials[] = {diffuse(0.7f), glossy(0.3f, 0.6f, 0.05f), glossy(0.3f, 0.6f, 0.5f),
                                             glossy(0.0f, 1.0f, 1.0f)};
        for (const ShadingMaterial& m : materials) {
            for (int i = 0; i < 20000; ++i) {
                const V3f a = squareToUniformHemisphere(rng.next2D());
                const V3f b = squareToUniformHemisphere(rng.next2D());
                const Rgb fab = bsdfEval(m, a, b), fba = bsdfEval(m, b, a);
                for (int c = 0; c < 3; ++c)
                    QVERIFY2(std::abs(fab[c] - fba[c]) <= 1e-5f * std::max(1.0f, fab[c]),
                             qPrintable(QString("f(a,b) %1 != f(b,a) %2").arg(fab[c]).arg(fba[c])));
            }
        }
    }

    void evalMatchesSpec() {
        Rng rng(17);
        for (float alpha : {0.05f, 0.3f, 1.0f}) {
            const ShadingMaterial m = glossy(0.25f, 0.5f, alpha);
            for (int i = 0; i < 20000; ++i) {
                const V3f wo = squareToUniformHemisphere(rng.next2D());
                const V3f wi = squareToUniformHemisphere(rng.next2D());
                if (wo.z < 1e-3f || wi.z < 1e-3f) continue;
                const double expected = specGlossy(0.25, 0.5, alpha, wo, wi);
                const double f = bsdfEval(m, wo, wi).x;
                QVERIFY2(std::abs(f - expected) <= 2e-4 * expected,
                         qPrintable(QString("f %1 vs SPEC %2").arg(f).arg(expected)));
            }
            // Other side: nothing.
            QVERIFY(isBlack(bsdfEval(m, direction(30), V3f(0.6f, 0, -0.8f))));
            QCOMPARE(bsdfPdf(m, direction(30), V3f(0.6f, 0, -0.8f)), 0.0f);
        }
    }

    void whiteFurnace_data() {
        QTest::addColumn<float>("albedo");
        QTest::addColumn<float>("specular");
        QTest::addColumn<float>("alpha");
        for (auto [a, s] : {std::pair{1.0f, 0.0f}, {0.0f, 1.0f}, {0.5f, 0.5f}, {0.2f, 0.8f}})
            for (float alpha : {0.05f, 0.3f, 1.0f})
                QTest::newRow(qPrintable(QString("albedo %1, specular %2, alpha %3").arg(a).arg(s).arg(alpha)))
                    << a << s << alpha;
    }
    void whiteFurnace() {
        // The directional albedo integral of f cos over the hemisphere must not exceed 1 when
        // albedo + specular <= 1 (separable Smith without Fresnel loses energy; it never gains).
        // Tolerance 1e-4: the quadrature is good to ~1e-6 here. The Monte Carlo mean of the
        // sample weights must agree with the quadrature (within 5 sigma + 1e-3): that is what a
        // path tracer actually uses.
        QFETCH(float, albedo);
        QFETCH(float, specular);
        QFETCH(float, alpha);
        const ShadingMaterial m = glossy(albedo, specular, alpha);
        for (double t : {0.0, 45.0, 70.0, 85.0, 89.9}) {
            const V3f wo = direction(t, 20.0);
            const double quad = integrateOverSphere(
                [&](const V3f& wi) { return double(bsdfEval(m, wo, wi).x) * std::max(0.0f, wi.z); });
            QVERIFY2(quad <= 1.0 + 1e-4, qPrintable(QString("wo %1 deg: albedo %2").arg(t).arg(quad, 0, 'g', 8)));
            if (specular == 0.0f) QVERIFY(std::abs(quad - albedo) < 1e-5);
            // Near normal incidence a smooth specular lobe loses almost nothing.
            if (specular == 1.0f && alpha <= 0.05f && t < 50.0) QVERIFY2(quad > 0.97, qPrintable(QString::number(quad)));
            Rng rng(hashSeed(checks_.nextSeed()));
            const int n = 200'000;
            double sum = 0.0, sum2 = 0.0;
            for (int i = 0; i < n; ++i) {
                BsdfSample s;
                const double w = bsdfSample(m, wo, rng.next2D(), rng.next1D(), s) ? s.weight.x : 0.0;
                sum += w;
                sum2 += w * w;
            }
            const double mean = sum / n, sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
            QVERIFY2(std::abs(mean - quad) <= 5.0 * sigma + 1e-3,
                     qPrintable(QString("wo %1 deg: MC %2 +- %3 vs quadrature %4").arg(t).arg(mean).arg(sigma).arg(quad)));
        }
    }

    void lobeProbability() {
        QCOMPARE(glossy(0.5f, 0.0f, 0.3f).diffuseLobeProb, 1.0f);
        QCOMPARE(glossy(0.0f, 0.5f, 0.3f).diffuseLobeProb, 0.0f);
        QCOMPARE(glossy(0.0f, 0.0f, 0.3f).diffuseLobeProb, 1.0f);
        QCOMPARE(glossy(0.01f, 1.0f, 0.3f).diffuseLobeProb, 0.1f);
        QCOMPARE(glossy(1.0f, 0.01f, 0.3f).diffuseLobeProb, 0.9f);
        QVERIFY(std::abs(glossy(0.3f, 0.6f, 0.3f).diffuseLobeProb - 1.0f / 3.0f) < 1e-6f);
        QCOMPARE(diffuse(0.5f).diffuseLobeProb, 1.0f);
        QCOMPARE(glossy(0.3f, 0.6f, 1e-9f).alpha, kMinGgxAlpha);
    }

    // --- Robustness ---------------------------------------------------------------------------

    void noNaNAtExtremes() {
        const V3f wos[] = {V3f(0, 0, 1), V3f(1, 0, 0), V3f(0.6f, 0.8f, 0), V3f(1, 0, 1e-7f),
                           V3f(0, 1, 1e-4f).normalized(), direction(89.99), V3f(0, 0, -1),
                           V3f(1, 0, -1e-7f)};
        const V2f us[] = {V2f(0, 0), V2f(0.5f, 0.5f), V2f(0.9999999f, 0.9999999f), V2f(1, 1),
                          V2f(0, 0.9999999f), V2f(0.9999999f, 0), V2f(0.25f, 0.75f)};
        const ShadingMaterial materials[] = {diffuse(1.0f), glossy(0.5f, 0.5f, 0.05f), glossy(0.0f, 1.0f, kMinGgxAlpha),
                                             glossy(0.0f, 1.0f, 1.0f), glossy(1.0f, 0.0f, 0.5f), dielectric(1.5f),
                                             dielectric(0.7f), dielectric(1.0f)};
        for (const ShadingMaterial& m : materials) {
            for (const V3f& wo : wos) {
                for (const V2f& u : us) {
                    for (float uLobe : {0.0f, 0.5f, 0.9999999f}) {
                        BsdfSample s;
                        if (bsdfSample(m, wo, u, uLobe, s)) {
                            QVERIFY(finite(s.wi) && std::abs(s.wi.length() - 1.0f) < 1e-4f);
                            QVERIFY(isFinite(s.weight) && s.weight.x >= 0 && s.weight.y >= 0 && s.weight.z >= 0);
                            QVERIFY(std::isfinite(s.pdf) && s.pdf >= 0);
                            QVERIFY(s.isDelta == m.isDelta());
                            if (!s.isDelta) QVERIFY(s.pdf > 0 && s.wi.z > 0);
                        }
                    }
                    // eval and pdf at a spread of wi, horizon and wi = wo, wi = -wo included.
                    for (const V3f& wi : {wo, -wo, squareToUniformSphere(u), V3f(1, 0, 0), V3f(0, 0, 1)}) {
                        QVERIFY(isFinite(bsdfEval(m, wo, wi)));
                        const float p = bsdfPdf(m, wo, wi);
                        QVERIFY(std::isfinite(p) && p >= 0);
                    }
                }
                QVERIFY(finite(sampleGGXVisibleNormal(V3f(wo.x, wo.y, std::max(0.0f, wo.z)).normalized(), 0.05f, V2f(0.3f, 0.9999999f))));
            }
        }
        // Two-sided materials: wo below or on the horizon is the caller's mistake; no sample.
        BsdfSample s;
        QVERIFY(!bsdfSample(glossy(0.5f, 0.5f, 0.3f), V3f(1, 0, 0), V2f(0.5f, 0.5f), 0.5f, s));
        QVERIFY(!bsdfSample(diffuse(0.5f), V3f(0, 0, -1), V2f(0.5f, 0.5f), 0.5f, s));
        // Warps at the corners of the square.
        for (const V2f& u : us) {
            QVERIFY(squareToCosineHemisphere(u).z >= 0);
            QVERIFY(squareToUniformDisk(u).length() <= 1.0f + 1e-6f);
            QVERIFY(squareToUniformCone(u, 0.9999f).z >= 0.9999f - 1e-6f);
            QVERIFY(finite(squareToUniformSphere(u)));
        }
    }

    // --- Delta materials ----------------------------------------------------------------------

    void mirrorAndEmitter() {
        Material mm;
        mm.type = MaterialType::Mirror;
        mm.reflectance = Rgbd(0.9, 0.5, 0.1);
        const ShadingMaterial mirror = ShadingMaterial::fromMaterial(mm);
        QVERIFY(mirror.isDelta() && !mirror.isEmitter());
        const V3f wo = direction(40.0, 33.0);
        BsdfSample s;
        QVERIFY(bsdfSample(mirror, wo, V2f(0.3f, 0.3f), 0.3f, s));
        QVERIFY(s.isDelta && !s.refracted && s.pdf == 0.0f);
        QVERIFY((s.wi - V3f(-wo.x, -wo.y, wo.z)).length() < 1e-6f);
        QCOMPARE(s.weight, Rgb(0.9f, 0.5f, 0.1f));
        QVERIFY(isBlack(bsdfEval(mirror, wo, s.wi)) && bsdfPdf(mirror, wo, s.wi) == 0.0f);

        Material me;
        me.type = MaterialType::Emitter;
        me.radiance = Rgbd(17, 12, 4);
        const ShadingMaterial lamp = ShadingMaterial::fromMaterial(me);
        QVERIFY(lamp.isEmitter() && !lamp.isDelta());
        QCOMPARE(lamp.radiance, Rgb(17, 12, 4));
        QVERIFY(!bsdfSample(lamp, wo, V2f(0.3f, 0.3f), 0.3f, s));
        QVERIFY(isBlack(bsdfEval(lamp, wo, direction(10))) && bsdfPdf(lamp, wo, direction(10)) == 0.0f);
    }

    void fresnelFormula() {
        // Normal incidence ((n-1)/(n+1))^2, grazing 1, and the sin/tan form at every angle, from
        // both sides (eta and 1/eta) and for ior < 1.
        QVERIFY(std::abs(fresnelDielectric(1.0f, 1.5f) - 0.04f) < 1e-6f);
        QVERIFY(std::abs(fresnelDielectric(-1.0f, 1.5f) - 0.04f) < 1e-6f);
        QCOMPARE(fresnelDielectric(0.0f, 1.5f), 1.0f);
        QCOMPARE(fresnelDielectric(1.0f, 1.0f), 0.0f);
        for (double ior : {1.5, 1.33, 2.4, 0.8}) {
            for (int i = 0; i <= 200; ++i) {
                const double cosI = std::max(1e-4, i / 200.0);
                // F has a square-root singularity at the critical angle: a float cosine there
                // can legitimately be far from the double one.
                const double sinI = std::sqrt(1.0 - cosI * cosI);
                if (std::abs(sinI / ior - 1.0) < 1e-3 || std::abs(sinI * ior - 1.0) < 1e-3) continue;
                const double out = fresnelBySines(cosI, 1.0, ior);      // from vacuum
                const double in = fresnelBySines(cosI, ior, 1.0);       // from inside
                QVERIFY2(std::abs(fresnelDielectric(float(cosI), float(ior)) - out) < 2e-5,
                         qPrintable(QString("ior %1 cos %2: %3 vs %4").arg(ior).arg(cosI).arg(fresnelDielectric(float(cosI), float(ior))).arg(out)));
                QVERIFY(std::abs(fresnelDielectric(float(-cosI), float(ior)) - in) < 2e-5);
            }
        }
        // Reciprocity: reflectance is the same for the two directions of one refracted ray.
        for (double t : {0.0, 20.0, 40.0, 60.0, 80.0}) {
            const double cosI = std::cos(t * std::numbers::pi / 180.0);
            const double sinT = std::sin(t * std::numbers::pi / 180.0) / 1.5;
            const double cosT = std::sqrt(1.0 - sinT * sinT);
            QVERIFY(std::abs(fresnelDielectric(float(cosI), 1.5f) - fresnelDielectric(float(-cosT), 1.5f)) < 1e-5f);
        }
    }

    void refractionObeysSnell() {
        for (float ior : {1.5f, 1.33f, 2.4f, 0.8f}) {
            const ShadingMaterial glass = dielectric(ior);
            for (double t = 0.0; t < 90.0; t += 2.5) {
                for (bool inside : {false, true}) {
                    V3f wo = direction(t, 37.0);
                    if (inside) wo.z = -wo.z;
                    const double n1 = inside ? ior : 1.0, n2 = inside ? 1.0 : ior;
                    const double sinI = std::sqrt(double(wo.x) * wo.x + double(wo.y) * wo.y);
                    const bool tir = n1 / n2 * sinI >= 1.0;
                    BsdfSample s;
                    QVERIFY(bsdfSample(glass, wo, V2f(0.5f, 0.5f), 0.9999999f, s));  // refract if possible
                    QVERIFY(s.isDelta && s.pdf == 0.0f && s.weight == Rgb(1.0f));
                    if (tir) {
                        if (n1 / n2 * sinI > 1.0 + 1e-5) {
                            QVERIFY(!s.refracted);
                            QVERIFY((s.wi - V3f(-wo.x, -wo.y, wo.z)).length() < 1e-6f);
                        }
                        continue;
                    }
                    QVERIFY(s.refracted);
                    QVERIFY(std::abs(s.wi.length() - 1.0f) < 1e-5f);
                    QVERIFY(s.wi.z * wo.z <= 0.0f);  // crosses the interface
                    const double sinT = std::sqrt(double(s.wi.x) * s.wi.x + double(s.wi.y) * s.wi.y);
                    QVERIFY2(std::abs(n1 * sinI - n2 * sinT) < 1e-5,
                             qPrintable(QString("ior %1, %2 deg, inside %3: %4 vs %5").arg(ior).arg(t).arg(inside).arg(n1 * sinI).arg(n2 * sinT)));
                    // Coplanar with the normal and on the opposite azimuth.
                    QVERIFY(std::abs(double(s.wi.x) * wo.y - double(s.wi.y) * wo.x) < 1e-6);
                    QVERIFY(double(s.wi.x) * wo.x + double(s.wi.y) * wo.y <= 1e-7);
                    // Reversible: refracting -wi's reverse from the other side gives wo back.
                    BsdfSample back;
                    QVERIFY(bsdfSample(glass, s.wi, V2f(0.5f, 0.5f), 0.9999999f, back));
                    QVERIFY(back.refracted && (back.wi - wo).length() < 1e-5f);
                }
            }
        }
        // ior 1: no reflection at all, straight through.
        BsdfSample s;
        const V3f wo = direction(50, 10);
        QVERIFY(bsdfSample(dielectric(1.0f), wo, V2f(0.1f, 0.1f), 0.0f, s));
        QVERIFY(s.refracted && (s.wi + wo).length() < 1e-6f);
    }

    void totalInternalReflection() {
        const ShadingMaterial glass = dielectric(1.5f);
        // Critical angle inside glass: asin(1/1.5) = 41.81 degrees.
        for (double t : {42.0, 50.0, 70.0, 89.0}) {
            V3f wo = direction(t, 15.0);
            wo.z = -wo.z;
            QCOMPARE(fresnelDielectric(wo.z, 1.5f), 1.0f);
            for (float uLobe : {0.0f, 0.5f, 0.9999999f}) {
                BsdfSample s;
                QVERIFY(bsdfSample(glass, wo, V2f(0.2f, 0.7f), uLobe, s));
                QVERIFY(!s.refracted && s.isDelta && s.weight == Rgb(1.0f));
                QVERIFY((s.wi - V3f(-wo.x, -wo.y, wo.z)).length() < 1e-6f);
            }
        }
        // ior < 1 seen from outside has a critical angle too: asin(0.8) = 53.13 degrees.
        BsdfSample s;
        QVERIFY(bsdfSample(dielectric(0.8f), direction(60.0), V2f(0.5f, 0.5f), 0.9999999f, s));
        QVERIFY(!s.refracted);
    }

    void fresnelChoiceFrequency_data() {
        QTest::addColumn<float>("ior");
        QTest::addColumn<double>("thetaDeg");
        QTest::addColumn<bool>("inside");
        QTest::newRow("ior 1.5, outside, 0 deg") << 1.5f << 0.0 << false;
        QTest::newRow("ior 1.5, outside, 45 deg") << 1.5f << 45.0 << false;
        QTest::newRow("ior 1.5, outside, 80 deg") << 1.5f << 80.0 << false;
        QTest::newRow("ior 1.5, inside, 20 deg") << 1.5f << 20.0 << true;
        QTest::newRow("ior 1.5, inside, 40 deg") << 1.5f << 40.0 << true;
        QTest::newRow("ior 1.33, inside, 30 deg") << 1.33f << 30.0 << true;
        QTest::newRow("ior 0.8, outside, 45 deg") << 0.8f << 45.0 << false;
    }
    void fresnelChoiceFrequency() {
        // The fraction reflected must be F (binomial; two-sided normal approximation, valid for
        // n F (1 - F) >> 1), with the uLobe stream drawn like a path tracer would.
        QFETCH(float, ior);
        QFETCH(double, thetaDeg);
        QFETCH(bool, inside);
        const ShadingMaterial glass = dielectric(ior);
        V3f wo = direction(thetaDeg, 70.0);
        if (inside) wo.z = -wo.z;
        const double f = fresnelBySines(std::abs(wo.z), inside ? ior : 1.0, inside ? 1.0 : ior);
        QVERIFY(f > 0.0 && f < 1.0);
        Rng rng(hashSeed(checks_.nextSeed()));
        const int n = 400'000;
        int reflected = 0;
        for (int i = 0; i < n; ++i) {
            BsdfSample s;
            QVERIFY(bsdfSample(glass, wo, rng.next2D(), rng.next1D(), s));
            QVERIFY(s.weight == Rgb(1.0f));  // F / F and (1 - F) / (1 - F): no eta^2
            if (!s.refracted) ++reflected;
        }
        const double z = (reflected - n * f) / std::sqrt(n * f * (1.0 - f));
        const double p = std::erfc(std::abs(z) / std::sqrt(2.0));
        const double sig = checks_.significance();
        qInfo("%s: reflected %d of %d, F = %.5f, z = %.2f, p = %.3g", QTest::currentDataTag(), reflected, n, f, z, p);
        QVERIFY2(p >= sig, qPrintable(QString("reflected fraction %1 vs F %2 (p = %3)").arg(double(reflected) / n).arg(f).arg(p)));
    }

private:
    lucerna::test::StatisticalChecks checks_{45, 20240626};
};

QTEST_APPLESS_MAIN(TestBsdfSampling)
#include "test_bsdf_sampling.moc"
