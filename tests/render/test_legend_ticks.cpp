// The legends' round steps (issue 40): render/display/legend_ticks.h's ticks over many ranges,
// checked against this file's own arithmetic for what "round" means (d x 10^k, d in 1, 2, 5),
// and the bands' colours and positions of a banded legend.

#include "render/display/false_colour.h"
#include "render/display/legend_ticks.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace lucerna;

namespace {

// d x 10^k with d in {1, 2, 5}, to a relative 1e-9.
bool round125(double v) {
    if (!(v > 0) || !std::isfinite(v)) return false;
    const double mantissa = v / std::pow(10.0, std::floor(std::log10(v)));
    for (double d : {1.0, 2.0, 5.0, 10.0})
        if (std::abs(mantissa - d) < 1e-9 * d) return true;
    return false;
}

QString describe(double lo, double hi, const char* scale, const std::vector<double>& ticks) {
    QStringList t;
    for (double v : ticks) t << QString::number(v, 'g', 17);
    return QString("%1 .. %2 (%3): %4").arg(lo, 0, 'g', 17).arg(hi, 0, 'g', 17).arg(scale, t.join(", "));
}

// A linear series: equal steps of a round length, every tick a multiple of it.
bool evenRoundSteps(const std::vector<double>& ticks) {
    if (ticks.size() < 2) return false;
    const double step = ticks[1] - ticks[0];
    if (!round125(step)) return false;
    for (size_t i = 1; i < ticks.size(); ++i)
        if (std::abs(ticks[i] - ticks[i - 1] - step) > 1e-6 * step) return false;
    const double k = ticks[0] / step;
    return std::abs(k - std::round(k)) < 1e-6;
}

}  // namespace

class TestLegendTicks : public QObject {
    Q_OBJECT
private slots:
    void designersRanges();
    void manyRanges();
    void degenerateRanges();
    void bandsAndTheirColours();
    void labels();
};

void TestLegendTicks::designersRanges() {
    // The office floor's plan read 703.4 / 640.3 / 583 / 530.7 / 483.2 lx.
    QCOMPARE(legendTicks(483.2, 703.4, LegendScale::Linear), (std::vector<double>{500, 550, 600, 650, 700}));
    // On a log scale the range holds one 1-2-5 value only (500): the linear ticks.
    QCOMPARE(legendTicks(483.2, 703.4, LegendScale::Logarithmic), (std::vector<double>{500, 550, 600, 650, 700}));
    // Its lux view read 1000 / 376.1 / 141.4 / 53.18 / 20.
    QCOMPARE(legendTicks(20, 1000, LegendScale::Logarithmic), (std::vector<double>{20, 50, 100, 200, 500, 1000}));
    QCOMPARE(legendTicks(20, 1000, LegendScale::Linear), (std::vector<double>{200, 400, 600, 800, 1000}));
    QCOMPARE(legendTicks(0, 1000, LegendScale::Linear), (std::vector<double>{0, 200, 400, 600, 800, 1000}));
    // Log over 0 has no logarithm: linear.
    QCOMPARE(legendTicks(0, 1000, LegendScale::Logarithmic), (std::vector<double>{0, 200, 400, 600, 800, 1000}));
    // Six decades: the powers of ten only.
    QCOMPARE(legendTicks(0.1, 10000, LegendScale::Logarithmic), (std::vector<double>{0.1, 1, 10, 100, 1000, 10000}));
}

void TestLegendTicks::manyRanges() {
    int checked = 0;
    for (int e = -12; e <= 12; e += 3)
        for (double m : {1.0, 1.37, 2.0, 4.83, 7.7})
            for (double ratio : {1.001, 1.05, 1.3, 2.0, 2.6, 4.0, 9.9, 10.0, 31.0, 150.0, 1e3, 4e4, 1e8}) {
                const double lo = m * std::pow(10.0, e), hi = lo * ratio;
                const double tol = 1e-9 * hi;
                for (LegendScale scale : {LegendScale::Linear, LegendScale::Logarithmic}) {
                    const char* name = scale == LegendScale::Linear ? "linear" : "log";
                    const std::vector<double> t = legendTicks(lo, hi, scale);
                    const QString what = describe(lo, hi, name, t);
                    QVERIFY2(t.size() >= 3 && t.size() <= 8, qPrintable(what));
                    for (size_t i = 0; i < t.size(); ++i) {
                        QVERIFY2(t[i] >= lo - tol && t[i] <= hi + tol, qPrintable(what));
                        if (i > 0) QVERIFY2(t[i] > t[i - 1], qPrintable(what));
                    }
                    if (scale == LegendScale::Linear) {
                        QVERIFY2(evenRoundSteps(t), qPrintable(what));
                    } else {
                        // Every tick 1, 2 or 5 times a power of ten; a range too narrow to hold
                        // three of them takes the linear ticks.
                        const bool allRound = std::all_of(t.begin(), t.end(), round125);
                        QVERIFY2(allRound || (ratio < 10 && evenRoundSteps(t)), qPrintable(what));
                        if (ratio >= 10) QVERIFY2(allRound, qPrintable(what));
                    }
                    ++checked;
                }
            }
    // Negative and mixed ranges, linear.
    for (auto [lo, hi] : {std::pair{-50.0, 50.0}, std::pair{-703.4, -483.2}, std::pair{-1e-3, 2e-3}}) {
        const std::vector<double> t = legendTicks(lo, hi, LegendScale::Linear);
        QVERIFY2(t.size() >= 3 && t.size() <= 8 && evenRoundSteps(t) && t.front() >= lo && t.back() <= hi,
                 qPrintable(describe(lo, hi, "linear", t)));
    }
    QVERIFY(checked > 1000);
}

void TestLegendTicks::degenerateRanges() {
    // A uniform grid: the ticks of the round range around its value, which they bracket.
    for (double v : {500.0, 483.2, 1e-7, 3e9, 0.0, -20.0}) {
        for (LegendScale scale : {LegendScale::Linear, LegendScale::Logarithmic, LegendScale::Bands}) {
            const std::vector<double> t = legendTicks(v, v, scale);
            const QString what = describe(v, v, "degenerate", t);
            QVERIFY2(t.size() >= 3 && t.size() <= 8, qPrintable(what));
            QVERIFY2(t.front() <= v && t.back() >= v, qPrintable(what));
            QVERIFY2(evenRoundSteps(t) || std::all_of(t.begin(), t.end(), round125), qPrintable(what));
        }
    }
    const TickRange r = roundRangeAround(500);
    QVERIFY(r.lo < 500 && r.hi > 500 && round125(r.lo) && round125(r.hi));
    // hi below lo: the same as a uniform grid at lo, not a flipped legend.
    QCOMPARE(legendTicks(700, 400, LegendScale::Linear), legendTicks(700, 700, LegendScale::Linear));
    // Nothing to tick without finite ends.
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(legendTicks(0, inf, LegendScale::Linear).empty());
    QVERIFY(legendTicks(nan, 10, LegendScale::Logarithmic).empty());
    QVERIFY(bandEdges(nan, 10).empty());
}

void TestLegendTicks::bandsAndTheirColours() {
    // 483.2 .. 703.4 lx in bands of 50 lx, from the round value below to the one above.
    const std::vector<double> edges = bandEdges(483.2, 703.4);
    QCOMPARE(edges, (std::vector<double>{450, 500, 550, 600, 650, 700, 750}));
    // A wide range: bands at 1, 2, 5 per decade.
    QCOMPARE(bandEdges(30, 2500), (std::vector<double>{20, 50, 100, 200, 500, 1000, 2000, 5000}));
    // Round ends stay: no empty band added.
    QCOMPARE(bandEdges(0, 1000), (std::vector<double>{0, 200, 400, 600, 800, 1000}));

    const Legend legend = makeLegend(483.2, 703.4, LegendScale::Bands, "lx");
    QCOMPARE(legend.scale(), LegendScale::Bands);
    QCOMPARE(legend.lo, 450.0);
    QCOMPARE(legend.hi, 750.0);
    QCOMPARE(legendTicks(legend), edges);
    const size_t n = edges.size() - 1;
    for (size_t k = 0; k < edges.size(); ++k) QCOMPARE(legendPosition(legend, edges[k]), double(k) / double(n));
    // One colour per band: its two ends' inner values alike, the next band's another.
    for (size_t k = 0; k < n; ++k) {
        const QColor a = legendColour(legend, edges[k] + 0.1), b = legendColour(legend, edges[k + 1] - 0.1);
        QCOMPARE(a, b);
        QCOMPARE(a, falseColourRamp((double(k) + 0.5) / double(n)));
        if (k + 1 < n) QVERIFY(legendColour(legend, edges[k + 1] + 0.1) != a);
    }
    // Below and above the range: the end bands' colours.
    QCOMPARE(legendColour(legend, 10), legendColour(legend, 460));
    QCOMPARE(legendColour(legend, 5000), legendColour(legend, 740));

    // The other scales keep their ramp: log puts the geometric middle halfway.
    const Legend log = makeLegend(10, 1000, LegendScale::Logarithmic, "lx");
    QCOMPARE(legendPosition(log, 100), 0.5);
    const Legend overZero = makeLegend(0, 1000, LegendScale::Logarithmic, "lx");
    QCOMPARE(overZero.scale(), LegendScale::Linear);
    QCOMPARE(legendPosition(overZero, 250), 0.25);
}

void TestLegendTicks::labels() {
    QCOMPARE(tickText(500), QString("500"));
    QCOMPARE(tickText(0.02), QString("0.02"));
    QCOMPARE(tickText(1500), QString("1500"));
    QCOMPARE(tickText(0.1 + 0.2), QString("0.3"));
    QCOMPARE(tickText(2e7), QString("2e+07"));
    QCOMPARE(tickText(-0.0), QString("0"));
    QVERIFY(isRoundValue(5e-9) && isRoundValue(200) && !isRoundValue(250) && !isRoundValue(0));
}

QTEST_GUILESS_MAIN(TestLegendTicks)
#include "test_legend_ticks.moc"
