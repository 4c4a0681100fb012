#include "render/display/legend_ticks.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {

constexpr int kMaxTicks = 8;
constexpr double kEps = 1e-9;  // relative slack: a tick at an end of the range counts as in it

// m x 10^e, exact where the decimal is (a division by an exact power of ten rounds once).
double roundValue(double m, int e) { return e >= 0 ? m * std::pow(10.0, e) : m / std::pow(10.0, -e); }

// A round step, 1, 2 or 5 times 10^e, as its mantissa's index (0, 1, 2) and exponent.
struct Step {
    int index = 0, exponent = 0;
    double mantissa() const { return index == 0 ? 1.0 : index == 1 ? 2.0 : 5.0; }
    double value() const { return roundValue(mantissa(), exponent); }
    Step next() const { return index == 2 ? Step{0, exponent + 1} : Step{index + 1, exponent}; }
    Step previous() const { return index == 0 ? Step{2, exponent - 1} : Step{index - 1, exponent}; }
};

// The largest round step below x (x > 0).
Step stepBelow(double x) {
    Step s{0, int(std::floor(std::log10(x))) + 1};
    while (s.value() >= x) s = s.previous();
    return s;
}

// The round values at or below x / at or above x (x > 0), of the 1-2-5 series.
double roundAtOrBelow(double x) {
    Step s = stepBelow(x);
    while (s.next().value() <= x * (1 + kEps)) s = s.next();
    return s.value();
}
double roundAtOrAbove(double x) {
    Step s = stepBelow(x);
    while (s.value() < x * (1 - kEps)) s = s.next();
    return s.value();
}

// The multiples of `step` in [lo, hi], k x m x 10^e computed so that they print plainly.
std::vector<double> multiples(double lo, double hi, Step step) {
    const double s = step.value(), slack = kEps * std::max(std::abs(lo), std::abs(hi));
    const double k0 = std::ceil((lo - slack) / s), k1 = std::floor((hi + slack) / s);
    std::vector<double> out;
    for (double k = k0; k <= k1 && out.size() <= size_t(kMaxTicks) + 1; ++k) {
        const double v = roundValue(k * step.mantissa(), step.exponent);
        out.push_back(v == 0 ? 0.0 : v);  // no -0
    }
    return out;
}

size_t countMultiples(double lo, double hi, Step step) {
    const double s = step.value(), slack = kEps * std::max(std::abs(lo), std::abs(hi));
    const double n = std::floor((hi + slack) / s) - std::ceil((lo - slack) / s) + 1;
    return n < 0 ? 0 : size_t(std::min(n, 1e9));
}

std::vector<double> linearTicks(double lo, double hi) {
    // From a step too fine (more than 8 ticks) up to the first giving 8 or fewer: the one before
    // gave 9 or more, so this one (at most 2.5 times longer) gives at least 3.
    Step step = stepBelow((hi - lo) / 10);
    while (countMultiples(lo, hi, step) > size_t(kMaxTicks)) step = step.next();
    return multiples(lo, hi, step);
}

// The 1-2-5 values in [lo, hi] (lo > 0), or, where more than 8, every `stride`-th power of ten.
std::vector<double> logTicks(double lo, double hi) {
    const int e0 = int(std::floor(std::log10(lo))) - 1, e1 = int(std::floor(std::log10(hi))) + 1;
    const auto inRange = [&](double v) { return v >= lo * (1 - kEps) && v <= hi * (1 + kEps); };
    std::vector<double> out;
    for (int e = e0; e <= e1; ++e)
        for (double m : {1.0, 2.0, 5.0})
            if (const double v = roundValue(m, e); inRange(v)) out.push_back(v);
    if (out.size() <= size_t(kMaxTicks)) return out;
    for (int stride = 1;; ++stride) {
        out.clear();
        for (int e = e0; e <= e1; ++e)
            if (e % stride == 0 && inRange(roundValue(1, e))) out.push_back(roundValue(1, e));
        if (out.size() <= size_t(kMaxTicks)) return out;
    }
}

}  // namespace

TickRange roundRangeAround(double value) {
    if (!std::isfinite(value) || value == 0) return {0, 1};
    const double a = std::abs(value);
    const TickRange r{roundAtOrBelow(0.8 * a), roundAtOrAbove(1.25 * a)};
    return value > 0 ? r : TickRange{-r.hi, -r.lo};
}

std::vector<double> legendTicks(double lo, double hi, LegendScale scale) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) return {};
    if (!(hi > lo)) {
        const TickRange r = roundRangeAround(lo);
        lo = r.lo, hi = r.hi;
    }
    if (scale == LegendScale::Bands) {
        std::vector<double> edges = bandEdges(lo, hi);
        edges.erase(std::remove_if(edges.begin(), edges.end(),
                                   [&](double v) { return v < lo - kEps * std::abs(lo) || v > hi + kEps * std::abs(hi); }),
                    edges.end());
        return edges;
    }
    if (scale == LegendScale::Logarithmic && lo > 0) {
        std::vector<double> ticks = logTicks(lo, hi);
        if (ticks.size() >= 3) return ticks;
    }
    return linearTicks(lo, hi);
}

std::vector<double> bandEdges(double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) return {};
    if (!(hi > lo)) {
        const TickRange r = roundRangeAround(lo);
        lo = r.lo, hi = r.hi;
    }
    const bool log = lo > 0 && hi > 10 * lo;
    std::vector<double> edges = log ? logTicks(lo, hi) : linearTicks(lo, hi);
    if (edges.size() < 2) return {lo, hi};
    const double a = edges[0], b = edges[1], y = edges[edges.size() - 2], z = edges.back();
    // One more band at either end that does not end on a round value.
    if (a > lo + kEps * std::abs(lo)) {
        double below = a - (b - a);
        if (log) below = b / a < 5 ? roundAtOrBelow(a * (1 - 1e-6)) : a / (b / a);
        edges.insert(edges.begin(), std::abs(below) < kEps * (b - a) ? 0.0 : below);
    }
    if (z < hi - kEps * std::abs(hi)) {
        double above = z + (z - y);
        if (log) above = z / y < 5 ? roundAtOrAbove(z * (1 + 1e-6)) : z * (z / y);
        edges.push_back(above);
    }
    return edges;
}

bool isRoundValue(double value) {
    if (!std::isfinite(value) || value == 0) return false;
    const double a = std::abs(value);
    const double r = roundAtOrBelow(a * (1 + 1e-12));
    return std::abs(r - a) <= 1e-9 * a || std::abs(roundAtOrAbove(a * (1 - 1e-12)) - a) <= 1e-9 * a;
}

QString tickText(double value) {
    if (value == 0) return QStringLiteral("0");
    const double a = std::abs(value);
    return QString::number(value, 'g', a >= 1e6 || a < 1e-4 ? 3 : 10);
}

}  // namespace lucerna
