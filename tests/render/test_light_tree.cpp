// The light tree (render/trace/lights/light_tree.h): its probabilities sum to one at any point, the
// lights it chooses follow them (chi-square), what sample() reports is what pmf() computes, and
// its bounds are conservative: no light that reaches a point has probability 0 there (an uplight,
// a wide spot, one-sided emitters seen from the front). Then next-event estimation's choice
// (tree_selection.h) over emitter clusters, delta lights, directional lights and the
// environment beside the tree: the same, for the probability bdpt's MIS weights read (pmf()).

#include "chi_square.h"
#include "render/trace/lights/light_tree.h"
#include "render/trace/lights/tree_selection.h"
#include "render/trace/rng.h"

#include <QtTest>

#include <cmath>

using namespace lucerna;

namespace {

V3f randomPoint(Rng& rng, float size) {
    return V3f(size * (rng.next1D() - 0.5f), size * 0.4f * rng.next1D(), size * (rng.next1D() - 0.5f));
}

V3f randomDirection(Rng& rng) {
    const float z = 1 - 2 * rng.next1D(), phi = 2 * kPi * rng.next1D();
    const float r = std::sqrt(std::max(0.0f, 1 - z * z));
    return V3f(r * std::cos(phi), r * std::sin(phi), z);
}

// A ceiling of downlights, a few uplights and wide spots, bare lamps and emissive triangles
// facing every way: the kinds of light a floor has, mixed.
struct MixedLights {
    std::vector<LightBounds> bounds;
    // Whether light i sends any light to p (the truth the bounds must respect).
    std::vector<std::function<bool(const V3f&)>> reaches;
};

MixedLights mixedLights(int count, uint64_t seed) {
    MixedLights m;
    Rng rng(seed);
    for (int i = 0; i < count; ++i) {
        const V3f p = randomPoint(rng, 30) + V3f(0, 1, 0);
        const float intensity = 0.1f + 10 * rng.next1D();
        switch (i % 5) {
        case 0:  // bare lamp
            m.bounds.push_back(LightBounds::point(p, intensity));
            m.reaches.push_back([](const V3f&) { return true; });
            break;
        case 1:  // downlight, 30 degrees
        case 2: {  // uplight (80 degrees) or a wide spot (170 degrees) pointing anywhere
            const bool down = i % 5 == 1;
            const V3f axis = down ? V3f(0, -1, 0) : (i % 2 ? V3f(0, 1, 0) : randomDirection(rng));
            const float cone = down ? radians(30.0f) : radians(i % 2 ? 80.0f : 170.0f);
            m.bounds.push_back(LightBounds::spot(p, axis, cone, intensity));
            m.reaches.push_back([p, axis, cone](const V3f& q) {
                const V3f w = (q - p).normalized();
                return std::acos(std::clamp(w.dot(axis), -1.0f, 1.0f)) < cone;
            });
            break;
        }
        default: {  // one-sided emissive triangle
            const V3f a = p, b = p + randomDirection(rng) * 0.5f, c = p + randomDirection(rng) * 0.5f;
            const V3f n = (b - a).cross(c - a);
            if (n.length2() < 1e-8f) {
                --i;
                continue;
            }
            m.bounds.push_back(LightBounds::triangle(a, b, c, n.normalized(), intensity));
            // Reaches q when q is in front of some part of it: in front of any vertex's plane.
            const V3f nn = n.normalized();
            m.reaches.push_back([a, nn](const V3f& q) { return (q - a).dot(nn) > 1e-3f; });
        }
        }
    }
    return m;
}

// Pearson's chi-square of `counts` (of n draws) against probabilities `expected`, cells with
// fewer than 5 expected pooled into one: true where the p-value exceeds `significance`.
bool frequenciesFollow(const std::vector<int64_t>& counts, const std::vector<double>& expected, int n,
                       double significance) {
    double stat = 0, pooledExpected = 0;
    int64_t pooledCount = 0;
    int cells = 0;
    for (size_t i = 0; i < counts.size(); ++i) {
        const double e = expected[i] * n;
        if (e < 5) {
            pooledExpected += e;
            pooledCount += counts[i];
            continue;
        }
        stat += (counts[i] - e) * (counts[i] - e) / e;
        ++cells;
    }
    if (pooledExpected > 0) {
        stat += (pooledCount - pooledExpected) * (pooledCount - pooledExpected) / std::max(pooledExpected, 1e-9);
        ++cells;
    }
    const double pValue = regularizedGammaQ(0.5 * (cells - 1), 0.5 * stat);
    if (pValue > significance) return true;
    qWarning("X^2 %g, %d cells, p %g", stat, cells, pValue);
    return false;
}

}  // namespace

class TestLightTree : public QObject {
    Q_OBJECT
private slots:
    void probabilitiesSumToOne() {
        for (const int count : {1, 2, 7, 300}) {
            const MixedLights m = mixedLights(count, 11 + count);
            const LightTree tree(m.bounds);
            Rng rng(5);
            double wasted = 0;  // the mean probability of a light that cannot reach the point
            for (int k = 0; k < 200; ++k) {
                const V3f p = randomPoint(rng, 40);
                double sum = 0;
                for (uint32_t i = 0; i < m.bounds.size(); ++i) {
                    sum += tree.pmf(p, i);
                    if (!m.reaches[i](p)) wasted += tree.pmf(p, i) / 200;
                }
                bool anyReaches = false;
                for (const auto& r : m.reaches) anyReaches = anyReaches || r(p);
                // Where no light can reach, the tree may know it (all zero) or not (its bounds are
                // loose); where one can, the probabilities are a distribution.
                if (anyReaches || sum > 0) QVERIFY2(std::abs(sum - 1) < 1e-4, qPrintable(QString::number(sum)));
            }
            qInfo("%d lights: a light that cannot reach chosen with probability %.3f", count, wasted);
        }
    }

    void conservativeBounds() {
        // Every light that reaches a point keeps a non-zero probability there: zero would be bias.
        const MixedLights m = mixedLights(400, 3);
        const LightTree tree(m.bounds);
        Rng rng(8);
        int checked = 0;
        for (int k = 0; k < 300; ++k) {
            const V3f p = randomPoint(rng, 40);
            for (uint32_t i = 0; i < m.bounds.size(); ++i)
                if (m.reaches[i](p)) {
                    ++checked;
                    QVERIFY2(tree.pmf(p, i) > 0, qPrintable(QString("light %1 (kind %2) at (%3, %4, %5)")
                                                                .arg(i).arg(i % 5).arg(p.x).arg(p.y).arg(p.z)));
                }
        }
        QVERIFY(checked > 10000);
    }

    void outsideACone() {
        // A spot's bound is tight where the light cannot go: behind a downlight, probability 0.
        const LightTree tree({LightBounds::spot(V3f(0, 3, 0), V3f(0, -1, 0), radians(30.0f), 5),
                              LightBounds::point(V3f(10, 3, 0), 1)});
        QVERIFY(tree.pmf(V3f(0, 5, 0), 0) == 0);
        QCOMPARE(tree.pmf(V3f(0, 5, 0), 1), 1.0f);
        QVERIFY(tree.pmf(V3f(0, 0, 0), 0) > tree.pmf(V3f(0, 0, 0), 1));  // under it, the spot wins
    }

    void chosenLightsFollowTheirProbabilities() {
        const MixedLights m = mixedLights(60, 21);
        const LightTree tree(m.bounds);
        Rng points(2);
        for (int k = 0; k < 3; ++k) {
            const V3f p = randomPoint(points, 30);
            std::vector<double> expected(m.bounds.size());
            for (uint32_t i = 0; i < m.bounds.size(); ++i) expected[i] = tree.pmf(p, i);
            std::vector<int64_t> counts(m.bounds.size(), 0);
            const int n = 200000;
            Rng rng(100 + k);
            for (int s = 0; s < n; ++s) {
                const auto choice = tree.sample(p, rng.next1D());
                QVERIFY(choice);
                // What sample() reports is what pmf() computes.
                QVERIFY(std::abs(choice->pmf - expected[choice->light]) <= 1e-5f * expected[choice->light]);
                ++counts[choice->light];
            }
            QVERIFY(frequenciesFollow(counts, expected, n, 0.001 / 3));
        }
    }

    void selectionPmfIsWhatSelectChooses() {
        // Two clusters of emissive triangles (a quad lamp facing down, a wall panel facing +x),
        // a point light, a spot, a directional light and the environment beside the tree.
        const auto triangle = [](uint32_t index, V3f a, V3f b, V3f c) {
            EmitterTriangle e;
            e.triangle = index;
            e.p0 = a;
            e.p1 = b;
            e.p2 = c;
            e.normal = (b - a).cross(c - a).normalized();
            e.area = 0.5f * (b - a).cross(c - a).length();
            e.radiance = Rgb(5, 5, 5);
            return e;
        };
        const std::vector<EmitterTriangle> emitters = {
            triangle(0, V3f(0, 3, 0), V3f(1, 3, 0), V3f(1, 3, 1)), triangle(1, V3f(0, 3, 0), V3f(1, 3, 1), V3f(0, 3, 1)),
            triangle(2, V3f(-4, 1, 0), V3f(-4, 1, 2), V3f(-4, 2, 0))};
        std::vector<DeltaLight> deltas(3);
        deltas[0].position = V3f(3, 2.5f, 3);
        deltas[0].intensity = Rgb(2, 2, 2);
        deltas[1].type = LightType::Spot;
        deltas[1].position = V3f(-2, 2.8f, -2);
        deltas[1].direction = V3f(0, -1, 0);
        deltas[1].cosCone = std::cos(radians(40.0f));
        deltas[1].intensity = Rgb(8, 8, 8);
        deltas[2].type = LightType::Directional;
        deltas[2].direction = V3f(0.3f, -1, 0.2f).normalized();
        deltas[2].intensity = Rgb(1, 1, 1);
        const size_t lights = emitters.size() + deltas.size() + 1;  // the environment last
        const TreeSelection selection(emitters, deltas, true, 1.0f, emitters.size());
        QVERIFY(!selection.empty());
        const struct {
            V3f p, n;
        } receivers[] = {{V3f(0.5f, 0, 0.5f), V3f(0, 1, 0)}, {V3f(-3, 1.5f, 1), V3f(-1, 0, 0)},
                         {V3f(2, 1, -1), V3f(0, 0, 0)}};
        for (const auto& r : receivers) {
            std::vector<double> expected(lights);
            double sum = 0;
            for (size_t i = 0; i < lights; ++i) sum += expected[i] = selection.pmf(i, r.p, r.n);
            QVERIFY2(std::abs(sum - 1) < 1e-5, qPrintable(QString("pmf sums to %1").arg(sum)));
            std::vector<int64_t> counts(lights, 0);
            const int n = 100000;
            Rng rng(7);
            for (int k = 0; k < n; ++k) {
                size_t index = 0;
                float pdf = 0;
                QVERIFY(selection.select(r.p, r.n, rng.next1D(), index, pdf));
                QVERIFY2(std::abs(pdf - expected[index]) <= 1e-5f * expected[index],
                         qPrintable(QString("light %1: select says %2, pmf %3").arg(index).arg(pdf).arg(expected[index])));
                ++counts[index];
            }
            QVERIFY(frequenciesFollow(counts, expected, n, 0.001 / 3));
        }
        // The quad lamp's two triangles (equal areas) share a leaf and split it by area.
        const V3f p(0.5f, 0, 0.5f), n(0, 1, 0);
        QVERIFY(selection.pmf(0, p, n) > 0 && selection.pmf(0, p, n) == selection.pmf(1, p, n));
    }

    void nearLightsFirst() {
        // A row of equal lamps: a point under one end chooses the near ones far more often than
        // the far ones (the power sampler would choose them all alike).
        std::vector<LightBounds> row;
        for (int i = 0; i < 100; ++i) row.push_back(LightBounds::point(V3f(float(i), 3, 0), 1));
        const LightTree tree(row);
        const V3f p(0, 0, 0);
        QVERIFY(tree.pmf(p, 0) > 20 * tree.pmf(p, 99));
        double nearShare = 0;
        for (uint32_t i = 0; i < 10; ++i) nearShare += tree.pmf(p, i);
        QVERIFY2(nearShare > 0.5, qPrintable(QString::number(nearShare)));
    }
};

QTEST_GUILESS_MAIN(TestLightTree)
#include "test_light_tree.moc"
