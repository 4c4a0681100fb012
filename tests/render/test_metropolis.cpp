// The Metropolis kernel of the `mir` backend (render/vpl/metropolis.h) on a small 2D
// target with a known integral:
//   - stationary density: many independent chains, each started from an exact sample of the
//     target (rejection sampling) and advanced k steps; their final states must follow the
//     target (chi-square, tests/support/chi_square.h). States along one chain are correlated and would
//     inflate the statistic, so every chain contributes exactly one state.
//   - a chain started anywhere converges to the target (burn-in) and the mean of the uniform
//     evaluations estimates the target's integral.
// A kernel with a wrong acceptance ratio (e.g. the MTM ratio without the reference set) fails
// the chi-square test: see brokenKernelIsDetected.

#include "render/vpl/metropolis.h"
#include "tests/support/chi_square.h"

#include <QtTest/QtTest>

#include <cmath>

using namespace lucerna;

namespace {

// Two Gaussian bumps on a floor, on [0,1]^2; integral in closed form (erf).
struct Target2D {
    struct Bump {
        double x, y, sigma, weight;
    };
    double floor = 0.05;
    Bump bumps[2] = {{0.3, 0.7, 0.08, 1.0}, {0.78, 0.22, 0.04, 0.6}};

    double operator()(double x, double y) const {
        double f = floor;
        for (const Bump& b : bumps) {
            const double dx = x - b.x, dy = y - b.y;
            f += b.weight * std::exp(-(dx * dx + dy * dy) / (2 * b.sigma * b.sigma));
        }
        return f;
    }
    double max() const { return floor + bumps[0].weight + bumps[1].weight; }
    double integral() const {
        const auto axis = [](double mu, double s) {
            return s * std::sqrt(std::numbers::pi / 2) * (std::erf((1 - mu) / (s * std::sqrt(2.0))) + std::erf(mu / (s * std::sqrt(2.0))));
        };
        double sum = floor;
        for (const Bump& b : bumps) sum += b.weight * axis(b.x, b.sigma) * axis(b.y, b.sigma);
        return sum;
    }
    // An exact sample by rejection from the uniform density.
    V2f sample(Rng& rng) const {
        for (;;) {
            const V2f p = rng.next2D();
            if (rng.nextDouble() * max() < (*this)(p.x, p.y)) return p;
        }
    }
};

struct NoPayload {};

MultipleTryMetropolis<NoPayload> makeChain(const Target2D& target, int tries, float largeStep) {
    MetropolisParams params;
    params.dimension = 2;
    params.tries = tries;
    params.largeStepProbability = largeStep;
    // Bigger small steps than the renderer's, so that k steps move well across the bumps.
    params.smallStepMin = 1.0f / 256.0f;
    params.smallStepMax = 1.0f / 8.0f;
    return MultipleTryMetropolis<NoPayload>(
        params, [&target](const std::vector<float>& u, NoPayload&) { return target(u[0], u[1]); });
}

}  // namespace

class TestMetropolis : public QObject {
    Q_OBJECT
private slots:
    void stationaryDensity_data();
    void stationaryDensity();
    void burnInAndNormalisation();
    void brokenKernelIsDetected();
};

void TestMetropolis::stationaryDensity_data() {
    QTest::addColumn<int>("tries");
    QTest::addColumn<float>("largeStep");
    QTest::addColumn<int>("steps");
    QTest::newRow("MH, small steps only") << 1 << 0.0f << 16;
    QTest::newRow("MH, large steps 0.3") << 1 << 0.3f << 16;
    QTest::newRow("MTM 4 tries, small steps only") << 4 << 0.0f << 16;
    QTest::newRow("MTM 4 tries, large steps 0.3") << 4 << 0.3f << 16;
}

void TestMetropolis::stationaryDensity() {
    QFETCH(int, tries);
    QFETCH(float, largeStep);
    QFETCH(int, steps);
    const Target2D target;
    const double norm = target.integral();
    auto chain = makeChain(target, tries, largeStep);
    const auto sample = [&](Rng& rng, V2f& out) {
        const V2f start = target.sample(rng);
        chain.setState({start.x, start.y});
        for (int i = 0; i < steps; ++i) chain.step(rng);
        out = V2f(chain.state()[0], chain.state()[1]);
        return true;
    };
    const auto pdf = [&](const V2f& p) { return target(p.x, p.y) / norm; };
    const ChiSquareResult r = chiSquareRect(sample, pdf, V2f(0, 0), V2f(1, 1), 24, 24, 200000, 11, 0.01 / 4);
    qInfo("%s; acceptance %.3f", r.message.c_str(), chain.acceptanceRate());
    QVERIFY(chain.acceptanceRate() > 0.05);  // the chains do move
    QVERIFY2(r.passed, r.message.c_str());
}

void TestMetropolis::burnInAndNormalisation() {
    // One long chain from a poor start (a corner): after burn-in its histogram has the target's
    // mass in the first bump's quadrant; the uniform evaluations estimate the integral.
    const Target2D target;
    auto chain = makeChain(target, 4, 0.3f);
    chain.setState({0.99f, 0.99f});
    Rng rng(5, 0);
    for (int i = 0; i < 2000; ++i) chain.step(rng);
    int inUpperLeft = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        chain.step(rng);
        if (chain.state()[0] < 0.5f && chain.state()[1] > 0.5f) ++inUpperLeft;
    }
    // Mass of the upper-left quadrant, numerically.
    double quadrant = 0;
    const int g = 400;
    for (int j = 0; j < g; ++j)
        for (int i = 0; i < g; ++i) {
            const double x = (i + 0.5) / g, y = (j + 0.5) / g;
            if (x < 0.5 && y > 0.5) quadrant += target(x, y);
        }
    quadrant /= double(g) * g * target.integral();
    const double observed = double(inUpperLeft) / n;
    qInfo("upper-left mass %.4f, expected %.4f; uniform mean %.5f over %lld, integral %.5f", observed, quadrant,
          chain.uniformMean(), chain.uniformCount(), target.integral());
    QVERIFY(std::abs(observed - quadrant) < 0.03);  // correlated samples: a generous bound
    QVERIFY(std::abs(chain.uniformMean() / target.integral() - 1.0) < 0.02);
}

void TestMetropolis::brokenKernelIsDetected() {
    // The harness can fail: a "chain" that always accepts the small-step proposal (a random walk,
    // stationary density uniform) must be rejected by the same test.
    const Target2D target;
    const double norm = target.integral();
    auto walk = makeChain(target, 1, 0.0f);
    MultipleTryMetropolis<NoPayload> uniformWalk(MetropolisParams{2, 1, 0.0f, 1.0f / 256.0f, 1.0f / 8.0f},
                                                 [](const std::vector<float>&, NoPayload&) { return 1.0; });
    const auto sample = [&](Rng& rng, V2f& out) {
        const V2f start = target.sample(rng);
        uniformWalk.setState({start.x, start.y});
        for (int i = 0; i < 4; ++i) uniformWalk.step(rng);
        out = V2f(uniformWalk.state()[0], uniformWalk.state()[1]);
        return true;
    };
    const auto pdf = [&](const V2f& p) { return target(p.x, p.y) / norm; };
    const ChiSquareResult r = chiSquareRect(sample, pdf, V2f(0, 0), V2f(1, 1), 24, 24, 200000, 12, 0.01);
    qInfo("%s", r.message.c_str());
    QVERIFY(!r.passed);
    (void)walk;
}

QTEST_GUILESS_MAIN(TestMetropolis)
#include "test_metropolis.moc"
