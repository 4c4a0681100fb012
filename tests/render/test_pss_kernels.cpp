// The primary-sample-space kernels of mlt and cmlt (render/trace/pss_sampler.h,
// render/progressive/cmlt/) keep a target's density: many independent chains, each started from
// an exact sample of a small 2D target and advanced k steps, compared by chi-square (one state per
// chain: states along a chain are correlated). A chain that forgets to restore rejected
// coordinates fails the same test; so does a greedy choice among the multiple-try caustic
// kernel's candidates. The backends built on them: test_mlt.

#include "render/progressive/cmlt/caustic_mutation.h"
#include "render/progressive/cmlt/lens_mutation.h"
#include "render/trace/pss_sampler.h"
#include "tests/support/chi_square.h"

#include <QtTest>

#include <cmath>
#include <functional>

using namespace lucerna;

namespace {

// A Gaussian bump and a ridge on a floor over [0,1]^2; normalised numerically.
double target(double x, double y) {
    const double dx = x - 0.3, dy = y - 0.65;
    return 0.05 + std::exp(-(dx * dx + dy * dy) / (2 * 0.08 * 0.08)) +
           0.5 * std::exp(-(x + y - 1.3) * (x + y - 1.3) / (2 * 0.03 * 0.03));
}

double targetIntegral() {
    double s = 0;
    const int n = 1000;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) s += target((i + 0.5) / n, (j + 0.5) / n);
    return s / (double(n) * n);
}

V2f exactSample(Rng& rng) {
    for (;;) {
        const V2f p = rng.next2D();
        if (rng.nextDouble() * 1.6 < target(p.x, p.y)) return p;
    }
}

// Chi-square of `sample`'s states against the normalised target on [0,1]^2 (24 x 24 cells,
// 100000 chains), the message logged.
ChiSquareResult chiSquareAgainstTarget(const std::function<bool(Rng&, V2f&)>& sample, uint64_t seed) {
    const double norm = targetIntegral();
    const auto pdf = [&](const V2f& p) { return target(p.x, p.y) / norm; };
    ChiSquareResult r = chiSquareRect(sample, pdf, V2f(0, 0), V2f(1, 1), 24, 24, 100000, seed, 0.01 / 3);
    qInfo("%s", r.message.c_str());
    return r;
}

// k Metropolis steps of a chain in primary sample space; `restore` false breaks reject().
V2f runChain(PssSampler& sampler, V2f start, int k, bool restore) {
    sampler.setState({start.x, start.y});
    double f = target(start.x, start.y);
    V2f current = start;
    for (int i = 0; i < k; ++i) {
        sampler.startIteration();
        const V2f y = sampler.next2D();
        const double fy = target(y.x, y.y);
        if (sampler.rng().nextDouble() < std::min(1.0, fy / f)) {
            sampler.accept();
            current = y;
            f = fy;
        } else if (restore) {
            sampler.reject();
        } else {
            sampler.accept();  // the bug: the proposal stays in u while the chain believes it did not move
        }
    }
    return current;
}

// The same with the target's x read from the camera stream and y from the light stream, and each
// step one of: Kelemen's small/large step, a light-stream step (the caustic perturbation), a
// camera-stream step.
V2f runMixedChain(PssSampler& sampler, V2f start, int k, Rng& choice) {
    sampler.setState({start.x});
    sampler.setCoordinate(SampleStream::Light, 0, start.y);
    double f = target(start.x, start.y);
    V2f current = start;
    for (int i = 0; i < k; ++i) {
        const double kind = choice.nextDouble();
        if (kind < 0.4) sampler.startStreamStep(SampleStream::Light);
        else if (kind < 0.6) sampler.startStreamStep(SampleStream::Camera);
        else sampler.startIteration();
        sampler.beginStream(SampleStream::Camera);
        const float x = sampler.next1D();
        sampler.beginStream(SampleStream::Light);
        const float y = sampler.next1D();
        const double fy = target(x, y);
        if (sampler.rng().nextDouble() < std::min(1.0, fy / f)) {
            sampler.accept();
            current = V2f(x, y);
            f = fy;
        } else {
            sampler.reject();
        }
    }
    return current;
}

// Reads the 2D point a sampler's state maps to: x from the camera stream, y from the light stream.
V2f readMixed(PssSampler& sampler) {
    sampler.beginStream(SampleStream::Camera);
    const float x = sampler.next1D();
    sampler.beginStream(SampleStream::Light);
    return V2f(x, sampler.next1D());
}

// Kelemen's steps mixed with cmlt's multiple-try caustic steps (CausticTries, chooseLensMove, as
// CmltChain::causticStep uses them); `greedy` breaks the choice.
V2f runCausticChain(PssSampler& sampler, V2f start, int k, int tries, bool greedy, Rng& choice) {
    sampler.setState({start.x});
    sampler.setCoordinate(SampleStream::Light, 0, start.y);
    double f = target(start.x, start.y);
    V2f current = start;
    CausticTries candidates;
    std::vector<double> fs(static_cast<size_t>(tries));
    std::vector<V2f> ys(static_cast<size_t>(tries));
    for (int i = 0; i < k; ++i) {
        if (choice.nextDouble() < 0.4) {
            sampler.startIteration();
            const V2f y = readMixed(sampler);
            const double fy = target(y.x, y.y);
            if (sampler.rng().nextDouble() < std::min(1.0, fy / f)) {
                sampler.accept();
                current = y;
                f = fy;
            } else {
                sampler.reject();
            }
            continue;
        }
        candidates.start(sampler, tries, sampler.rng());
        for (int j = 0; j < tries; ++j) {
            ys[size_t(j)] = readMixed(candidates.candidate(j));
            fs[size_t(j)] = target(ys[size_t(j)].x, ys[size_t(j)].y);
        }
        LensMove m = chooseLensMove(fs, f, sampler.rng());
        if (greedy) {  // the bug: always the best candidate, then Metropolis on it
            m.candidate = int(std::max_element(fs.begin(), fs.end()) - fs.begin());
            m.accepted = sampler.rng().nextDouble() < std::min(1.0, fs[size_t(m.candidate)] / f);
        }
        if (m.accepted) {
            sampler = candidates.candidate(m.candidate);
            sampler.accept();
            current = ys[size_t(m.candidate)];
            f = fs[size_t(m.candidate)];
        }
    }
    return current;
}


}  // namespace

class TestPssKernels : public QObject {
    Q_OBJECT
private slots:
    void stationaryDensity_data();
    void stationaryDensity();
    void streamStepsKeepTheDensity();
    void lensKernelStationaryDensity_data() { kernelTries(); }
    void lensKernelStationaryDensity();
    void causticKernelStationaryDensity_data() { kernelTries(); }
    void causticKernelStationaryDensity();

private:
    // The multiple-try kernels' rows: one try, four, and four with a greedy choice (must fail).
    static void kernelTries() {
        QTest::addColumn<int>("tries");
        QTest::addColumn<bool>("greedy");
        QTest::addColumn<bool>("shouldPass");
        QTest::newRow("1 try") << 1 << false << true;
        QTest::newRow("4 tries") << 4 << false << true;
        QTest::newRow("4 tries, greedy choice (broken)") << 4 << true << false;
    }
};

void TestPssKernels::stationaryDensity_data() {
    QTest::addColumn<float>("largeStep");
    QTest::addColumn<bool>("restore");
    QTest::addColumn<bool>("shouldPass");
    QTest::newRow("small steps only") << 0.0f << true << true;
    QTest::newRow("large steps 0.3") << 0.3f << true << true;
    QTest::newRow("rejections not restored (broken)") << 0.0f << false << false;
}

void TestPssKernels::stationaryDensity() {
    QFETCH(float, largeStep);
    QFETCH(bool, restore);
    QFETCH(bool, shouldPass);
    long long chains = 0;
    const auto sample = [&](Rng& rng, V2f& out) {
        // Larger small steps than the renderer's 0.01, so that 12 steps move across the bump.
        PssSampler sampler(hashSeed(7, uint64_t(++chains)), 0.06f, largeStep);
        out = runChain(sampler, exactSample(rng), 12, restore);
        return true;
    };
    const ChiSquareResult r = chiSquareAgainstTarget(sample, 3);
    QCOMPARE(r.passed, shouldPass);
}

// Stream steps (pss_sampler.h) mixed with Kelemen's: a stream left alone by a step must not move,
// and one that missed steps must catch up with exactly the steps its stream took.
void TestPssKernels::streamStepsKeepTheDensity() {
    long long chains = 0;
    Rng choice(11, 0);
    const auto sample = [&](Rng& rng, V2f& out) {
        PssSampler sampler(hashSeed(8, uint64_t(++chains)), 0.06f, 0.1f);
        out = runMixedChain(sampler, exactSample(rng), 16, choice);
        return true;
    };
    const ChiSquareResult r = chiSquareAgainstTarget(sample, 4);
    QVERIFY2(r.passed, r.message.c_str());

    // A light-stream step leaves the camera stream's number where it was, accepted or not.
    PssSampler sampler(5, 0.06f, 0.0f);
    sampler.setState({0.25f});
    sampler.setCoordinate(SampleStream::Light, 0, 0.5f);
    for (int i = 0; i < 20; ++i) {
        sampler.startStreamStep(SampleStream::Light);
        sampler.beginStream(SampleStream::Camera);
        QCOMPARE(sampler.next1D(), 0.25f);
        sampler.beginStream(SampleStream::Light);
        const float y = sampler.next1D();
        QVERIFY(y != 0.5f);
        if (i % 2) sampler.accept();
        else sampler.reject();
    }
}

void TestPssKernels::lensKernelStationaryDensity() {
    // cmlt's lens kernel (perturbRaster, chooseLensMove) on an "image" of 64 x 48 pixels whose
    // contribution is the 2D target: chains from exact samples, 12 steps each, one state per
    // chain. Sigma is large enough to cross the image's edges, so the wrap-around is exercised.
    QFETCH(int, tries);
    QFETCH(bool, greedy);
    QFETCH(bool, shouldPass);
    const float w = 64, h = 48;
    const auto f = [&](const V2f& r) { return target(r.x / w, r.y / h); };
    std::vector<double> fs(static_cast<size_t>(tries));
    std::vector<V2f> ys(static_cast<size_t>(tries));
    const auto sample = [&](Rng& rng, V2f& out) {
        const V2f s = exactSample(rng);
        V2f x(s.x * w, s.y * h);
        for (int k = 0; k < 12; ++k) {
            for (int i = 0; i < tries; ++i) {
                ys[size_t(i)] = perturbRaster(x, 6.0f, w, h, rng);
                fs[size_t(i)] = f(ys[size_t(i)]);
            }
            if (greedy) {  // the bug: always the best candidate, then Metropolis on it
                const size_t best = size_t(std::max_element(fs.begin(), fs.end()) - fs.begin());
                if (rng.nextDouble() < std::min(1.0, fs[best] / f(x))) x = ys[best];
                continue;
            }
            const LensMove m = chooseLensMove(fs, f(x), rng);
            if (m.accepted) x = ys[size_t(m.candidate)];
        }
        out = V2f(x.x / w, x.y / h);
        return true;
    };
    const ChiSquareResult r = chiSquareAgainstTarget(sample, 5);
    QCOMPARE(r.passed, shouldPass);
}

void TestPssKernels::causticKernelStationaryDensity() {
    QFETCH(int, tries);
    QFETCH(bool, greedy);
    QFETCH(bool, shouldPass);
    long long chains = 0;
    Rng choice(13, 0);
    const auto sample = [&](Rng& rng, V2f& out) {
        PssSampler sampler(hashSeed(9, uint64_t(++chains)), 0.06f, 0.1f);
        out = runCausticChain(sampler, exactSample(rng), 16, tries, greedy, choice);
        return true;
    };
    const ChiSquareResult r = chiSquareAgainstTarget(sample, 6);
    QCOMPARE(r.passed, shouldPass);
}

QTEST_APPLESS_MAIN(TestPssKernels)
#include "test_pss_kernels.moc"
