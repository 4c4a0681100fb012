// The sample generators: PCG32 streams and the Owen-scrambled Sobol sampler.

#include "render/trace/sobol_sampler.h"

#include <QtTest>

#include <set>

using namespace lucerna;

class TestSampleGenerators : public QObject {
    Q_OBJECT
private slots:
    void dimension1TablesMatchGeneratorMatrix();
    void everyPairIsAZeroTwoNet();
    void uniformOverManyPixels();
};

void TestSampleGenerators::dimension1TablesMatchGeneratorMatrix() {
    Rng rng(3);
    for (int n = 0; n < 100000; ++n) {
        const uint32_t i = n < 1000 ? uint32_t(n) : rng.nextUint();
        uint32_t expected = 0, bits = i;
        for (uint32_t v = 1u << 31; bits; bits >>= 1, v ^= v >> 1)
            if (bits & 1u) expected ^= v;
        QCOMPARE(sobol::dimension1(i), expected);
    }
}

void TestSampleGenerators::everyPairIsAZeroTwoNet() {
    // The first 2^m samples of a pixel put exactly one point in each elementary interval of area
    // 2^-m (here the 2^a x 2^(m-a) grids), for every stratified pair of dimensions: the property
    // that Owen scrambling and the index shuffle must keep.
    const int m = 6, n = 1 << m;
    for (uint64_t pixel : {0ull, 1ull, 987654321ull}) {
        std::vector<std::vector<V2f>> pairs(SobolSampler::kStratifiedDimensions / 2);
        for (int i = 0; i < n; ++i) {
            SobolSampler s(pixel, uint32_t(i));
            for (auto& p : pairs) p.push_back(s.next2D());
        }
        for (const auto& points : pairs)
            for (int a = 0; a <= m; ++a) {
                std::set<std::pair<int, int>> cells;
                for (const V2f& p : points) cells.insert({int(p.x * (1 << a)), int(p.y * (1 << (m - a)))});
                QCOMPARE(int(cells.size()), n);
            }
    }
}

void TestSampleGenerators::uniformOverManyPixels() {
    // Over many pixels, every dimension (stratified and padded) is uniform: 16 bins, chi-square
    // against 15 degrees of freedom at p = 1e-4 (critical value 44.3).
    const int pixels = 20000, bins = 16, dims = 24;
    std::vector<std::vector<int>> counts(dims, std::vector<int>(bins, 0));
    for (int p = 0; p < pixels; ++p) {
        SobolSampler s(hashSeed(7, uint64_t(p)), uint32_t(p % 5));
        for (int d = 0; d < dims; d += 2) {
            const V2f u = s.next2D();
            QVERIFY(u.x >= 0 && u.x < 1 && u.y >= 0 && u.y < 1);
            ++counts[d][int(u.x * bins)];
            ++counts[d + 1][int(u.y * bins)];
        }
    }
    for (int d = 0; d < dims; ++d) {
        double chi2 = 0;
        const double expected = double(pixels) / bins;
        for (int c : counts[d]) chi2 += (c - expected) * (c - expected) / expected;
        QVERIFY2(chi2 < 44.3, qPrintable(QString("dimension %1: chi2 %2").arg(d).arg(chi2)));
    }
}

QTEST_APPLESS_MAIN(TestSampleGenerators)
#include "test_sample_generators.moc"
