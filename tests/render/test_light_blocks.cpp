// The preview's choice of the lights each block of the image shades in full
// (render/preview/light_blocks.h): the bound holds at every point of a block, the choice is the
// strongest by that bound.

#include "render/preview/light_blocks.h"
#include "render/trace/rng.h"

#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace lucerna;

namespace {

BlockBounds box(const V3f& lo, const V3f& hi) {
    BlockBounds b;
    b.lo = lo;
    b.hi = hi;
    b.empty = false;
    return b;
}

V3f randomIn(Rng& rng, const V3f& lo, const V3f& hi) {
    return V3f(lo.x + (hi.x - lo.x) * rng.next1D(), lo.y + (hi.y - lo.y) * rng.next1D(), lo.z + (hi.z - lo.z) * rng.next1D());
}

}  // namespace

class TestLightBlocks : public QObject {
    Q_OBJECT
private slots:
    // What a point or spot light gives at any point of the block (intensity / d^2, zero outside
    // a spot's cone) never exceeds the block's bound, and a zero bound means no point of the
    // block is inside the cone.
    void boundHoldsOverTheBlock() {
        Rng rng(7, 1);
        int zeroBounds = 0, checked = 0;
        for (int trial = 0; trial < 400; ++trial) {
            const V3f lo = randomIn(rng, V3f(-5, -5, -5), V3f(5, 5, 5));
            const BlockBounds b = box(lo, lo + randomIn(rng, V3f(0, 0, 0), V3f(3, 1, 3)));
            const V3f at = randomIn(rng, V3f(-8, -8, -8), V3f(8, 8, 8));
            const bool spot = trial % 2 == 1;
            V3f axis = randomIn(rng, V3f(-1, -1, -1), V3f(1, 1, 1));
            axis.normalize();
            const float cone = 0.3f + 1.0f * rng.next1D();  // radians
            const float intensity = 1.0f + 100.0f * rng.next1D();
            const LightBounds light = spot ? LightBounds::spot(at, axis, cone, intensity) : LightBounds::point(at, intensity);
            const float bound = blockImportance(ImportanceBounds(light), b);
            if (bound == 0) ++zeroBounds;
            for (int k = 0; k < 200; ++k) {
                const V3f p = randomIn(rng, b.lo, b.hi);
                const V3f d = p - at;
                const bool lit = !spot || d.normalized().dot(axis) >= std::cos(cone) + 1e-4f;
                const float e = lit ? intensity / d.length2() : 0.0f;
                QVERIFY2(e <= bound * 1.0001f, qPrintable(QString("trial %1: %2 > bound %3").arg(trial).arg(e).arg(bound)));
                ++checked;
            }
        }
        QVERIFY(zeroBounds > 10);  // spots aimed away were ruled out, so the check saw both cases
        QVERIFY(checked == 80000);
        QCOMPARE(blockImportance(ImportanceBounds(LightBounds::point(V3f(0, 0, 0), 5)), BlockBounds()), 0.0f);
    }

    // Each block's list, found by descending the light tree, is the lights of the largest bound
    // (as every light's bound would rank them), strongest first; an empty block gets none (-1).
    void choosesTheStrongest() {
        Rng rng(3, 2);
        std::vector<LightBounds> lights;
        for (int i = 0; i < 300; ++i) {
            const V3f at = randomIn(rng, V3f(0, 3, 0), V3f(30, 3, 20));
            const float intensity = 1.0f + rng.next1D();
            lights.push_back(i % 3 == 0 ? LightBounds::spot(at, V3f(0, -1, 0), 0.4f + rng.next1D(), intensity)
                                        : LightBounds::point(at, intensity));
        }
        // A spot aimed at the ceiling: it can light none of the blocks on the floor.
        lights.push_back(LightBounds::spot(V3f(15, 2.9f, 10), V3f(0, 1, 0), 0.5f, 1000.0f));
        const LightTree tree(lights);
        std::vector<BlockBounds> blocks;
        for (int i = 0; i < 12; ++i) {
            const V3f lo = randomIn(rng, V3f(0, 0, 0), V3f(28, 0, 18));
            blocks.push_back(box(lo, lo + V3f(2, 0.8f, 2)));
        }
        blocks.push_back(BlockBounds());
        const int k = 5;
        const std::vector<int32_t> chosen = chooseBlockLights(blocks, tree, k);
        QCOMPARE(chosen.size(), blocks.size() * size_t(k));
        for (size_t b = 0; b + 1 < blocks.size(); ++b) {
            std::vector<float> score;
            for (const LightBounds& l : lights) score.push_back(blockImportance(ImportanceBounds(l), blocks[b]));
            std::vector<float> sorted = score;
            std::sort(sorted.rbegin(), sorted.rend());
            for (int r = 0; r < k; ++r) {
                const int32_t j = chosen[b * k + size_t(r)];
                QVERIFY(j >= 0 && j < 300);  // never the spot aimed away
                QCOMPARE(score[size_t(j)], sorted[size_t(r)]);
            }
        }
        for (int r = 0; r < k; ++r) QCOMPARE(chosen[(blocks.size() - 1) * k + size_t(r)], -1);
    }
};

QTEST_APPLESS_MAIN(TestLightBlocks)
#include "test_light_blocks.moc"
