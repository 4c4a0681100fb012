#include "tests/support/chi_square.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

namespace lucerna {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kMinExpected = 5.0;        // Pearson's rule of thumb for pooling
constexpr double kStrayFraction = 1e-5;     // tolerated samples where the pdf integrates to 0
constexpr double kIntegralSlack = 1e-3;     // a pdf may integrate to at most 1 + this
constexpr double kCellAbsEps = 1e-12;       // integration tolerance per cell: absolute,
constexpr double kCellRelEps = 1e-6;        // and relative to the cell's integral
constexpr int kMaxDepth = 12;               // adaptive Simpson: levels below the initial panels
constexpr int kPanels = 4;                  // initial panels: a peak narrower than the cell/8
                                            // would otherwise be missed by the first 5 points

// --- Numerical integration -------------------------------------------------------------------

template <class F>
double simpsonRec(const F& f, double a, double b, double fa, double fm, double fb, double whole,
                  double eps, int depth) {
    const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
    const double flm = f(lm), frm = f(rm);
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const double delta = left + right - whole;
    if (depth <= 0 || std::abs(delta) <= 15.0 * eps) return left + right + delta / 15.0;
    return simpsonRec(f, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1) +
           simpsonRec(f, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1);
}

// eps is absolute, or relEps times the magnitude of the first estimate if that is larger: the
// pdfs are float computations whose rounding noise (~1e-7 relative) an absolute tolerance far
// below it would chase down to the maximum depth everywhere.
template <class F>
double adaptiveSimpson(const F& f, double a, double b, double absEps, double relEps) {
    const double h = (b - a) / kPanels;
    double pa[kPanels], pb[kPanels], fa[kPanels], fm[kPanels], fb[kPanels], whole[kPanels];
    double magnitude = 0.0;
    for (int i = 0; i < kPanels; ++i) {
        pa[i] = a + i * h;
        pb[i] = (i + 1 == kPanels) ? b : a + (i + 1) * h;
        fa[i] = i == 0 ? f(pa[i]) : fb[i - 1];
        fm[i] = f(0.5 * (pa[i] + pb[i]));
        fb[i] = f(pb[i]);
        whole[i] = (pb[i] - pa[i]) / 6.0 * (fa[i] + 4.0 * fm[i] + fb[i]);
        magnitude += std::abs(whole[i]);
    }
    const double eps = std::max(absEps, relEps * magnitude) / kPanels;
    double sum = 0.0;
    for (int i = 0; i < kPanels; ++i)
        sum += simpsonRec(f, pa[i], pb[i], fa[i], fm[i], fb[i], whole[i], eps, kMaxDepth);
    return sum;
}

// Integral of g(x, y) over [x0, x1] x [y0, y1], as nested 1D adaptive Simpson. The inner
// tolerances are 10x tighter so that the outer level does not chase inner noise.
template <class G>
double integrate2D(const G& g, double x0, double x1, double y0, double y1) {
    const double innerAbs = 0.1 * kCellAbsEps / std::max(x1 - x0, 1e-300);
    auto outer = [&](double x) {
        return adaptiveSimpson([&](double y) { return g(x, y); }, y0, y1, innerAbs, 0.1 * kCellRelEps);
    };
    return adaptiveSimpson(outer, x0, x1, kCellAbsEps, kCellRelEps);
}

// Direction for z = cos(theta) and phi; dOmega = dz dphi in these coordinates.
V3f sphereDirection(double z, double phi) {
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return V3f(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
}

// Claimed pdf as the integrand; a negative or non-finite pdf is recorded (and contributes 0).
struct PdfGuard {
    bool bad = false;
    double operator()(double v) {
        if (!std::isfinite(v) || v < 0.0) {
            bad = true;
            return 0.0;
        }
        return v;
    }
};

// --- Incomplete gamma (Numerical Recipes 6.2) ---------------------------------------------------

double gammaPSeries(double a, double x) {
    double ap = a, del = 1.0 / a, sum = del;
    for (int n = 0; n < 100000; ++n) {
        ap += 1.0;
        del *= x / ap;
        sum += del;
        if (std::abs(del) < std::abs(sum) * 1e-15) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

double gammaQContinuedFraction(double a, double x) {
    constexpr double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 100000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double del = d * c;
        h *= del;
        if (std::abs(del - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// --- The test proper ---------------------------------------------------------------------------

struct Category {
    double expected = 0;
    int64_t observed = 0;
    int cell = -1;  // index into the histogram; -1 = failures, -2 = pool
};

std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
    char buf[256];
    std::snprintf(buf, sizeof buf, f, a, b, c, d);
    return buf;
}

// Shared by the sphere and rectangle tests once counts and expectations are known.
ChiSquareResult evaluate(const std::vector<double>& cellIntegral, const std::vector<int64_t>& counts,
                         int64_t sampleCount, int64_t failed, int64_t offDomain, int64_t invalid,
                         bool badPdf, double significance,
                         const std::function<std::string(int)>& describeCell) {
    ChiSquareResult r;
    r.samples = sampleCount;
    r.failedSamples = failed;
    r.significance = significance;
    const double n = double(sampleCount);

    double integral = 0.0;
    for (double v : cellIntegral) integral += v;
    r.pdfIntegral = integral;

    std::vector<Category> cats;
    int64_t strays = offDomain;
    for (size_t i = 0; i < cellIntegral.size(); ++i) {
        const double e = cellIntegral[i] * n;
        if (e > 0.0)
            cats.push_back({e, counts[i], int(i)});
        else
            strays += counts[i];
    }
    // Failures are a category of their own, expected with probability 1 - integral: a sampler
    // that fails more or less often than its pdf's mass says is caught here.
    const double failExpected = std::max(0.0, (1.0 - integral) * n);
    if (failExpected > 0.0)
        cats.push_back({failExpected, failed, -1});
    else
        strays += failed;
    r.strayedSamples = strays;

    // Pool the categories with small expectations (smallest first) until the pool itself has
    // enough, so that the chi-square approximation of the statistic holds.
    std::sort(cats.begin(), cats.end(),
              [](const Category& a, const Category& b) { return a.expected < b.expected; });
    std::vector<Category> used;
    Category pool{0.0, 0, -2};
    for (const Category& c : cats) {
        if (c.expected < kMinExpected || (pool.expected > 0.0 && pool.expected < kMinExpected)) {
            pool.expected += c.expected;
            pool.observed += c.observed;
            ++r.pooledCells;
        } else {
            used.push_back(c);
        }
    }
    if (pool.expected > 0.0) used.push_back(pool);

    struct Contribution {
        double value;
        Category cat;
    };
    std::vector<Contribution> contributions;
    for (const Category& c : used) {
        const double d = double(c.observed) - c.expected;
        const double v = d * d / c.expected;
        r.statistic += v;
        contributions.push_back({v, c});
    }
    r.degreesOfFreedom = int(used.size()) - 1;
    r.pValue = r.degreesOfFreedom > 0 ? chiSquarePValue(r.statistic, r.degreesOfFreedom) : 0.0;

    std::string summary = fmt("X^2 = %.2f, dof = %.0f, p = %.3g (significance %.3g)", r.statistic,
                              r.degreesOfFreedom, r.pValue, significance) +
                          fmt(", pdf integral = %.6f, failed %.0f of %.0f, pooled %.0f cells",
                              integral, double(failed), n, r.pooledCells);
    if (strays > 0) summary += fmt(", %.0f strayed", double(strays));

    std::vector<std::string> problems;
    if (invalid > 0) problems.push_back(fmt("%.0f samples were not finite unit vectors", double(invalid)));
    if (badPdf) problems.push_back("the pdf returned a negative or non-finite value");
    if (integral > 1.0 + kIntegralSlack)
        problems.push_back(fmt("the pdf integrates to %.6f > 1", integral));
    if (double(strays) > kStrayFraction * n)
        problems.push_back(fmt("%.0f samples landed where the pdf integrates to 0 (or off the domain)",
                               double(strays)));
    if (r.degreesOfFreedom < 1) problems.push_back("fewer than 2 categories: use more samples or cells");
    else if (!(r.pValue >= significance))
        problems.push_back("p-value below the significance level");

    r.passed = problems.empty();
    if (r.passed) {
        r.message = summary;
        return r;
    }
    std::string msg = "chi-square test failed: ";
    for (size_t i = 0; i < problems.size(); ++i) msg += (i ? "; " : "") + problems[i];
    msg += ". " + summary + ". Largest contributions:";
    std::sort(contributions.begin(), contributions.end(),
              [](const Contribution& a, const Contribution& b) { return a.value > b.value; });
    for (size_t i = 0; i < std::min<size_t>(5, contributions.size()); ++i) {
        const Category& c = contributions[i].cat;
        const std::string where = c.cell >= 0 ? describeCell(c.cell)
                                  : c.cell == -1 ? std::string("failed samples")
                                                 : std::string("pooled cells");
        msg += "\n  " + where + fmt(": observed %.0f, expected %.1f, contributes %.1f",
                                    double(c.observed), c.expected, contributions[i].value);
    }
    r.message = msg;
    return r;
}

}  // namespace

double regularizedGammaQ(double a, double x) {
    if (!(a > 0.0) || !(x >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
    if (x == 0.0) return 1.0;
    if (std::isinf(x)) return 0.0;
    // The series converges fast below a + 1, the continued fraction above (and keeps tiny
    // p-values accurate there, where 1 - P would cancel).
    if (x < a + 1.0) return std::clamp(1.0 - gammaPSeries(a, x), 0.0, 1.0);
    return std::clamp(gammaQContinuedFraction(a, x), 0.0, 1.0);
}

ChiSquareResult chiSquareSphere(const std::function<bool(Rng&, V3f&)>& sample,
                                const std::function<double(const V3f&)>& pdf, int thetaBins,
                                int phiBins, int sampleCount, uint64_t seed, double significance) {
    return chiSquareSphereCap(sample, pdf, -1.0, thetaBins, phiBins, sampleCount, seed,
                              significance);
}

ChiSquareResult chiSquareSphereCap(const std::function<bool(Rng&, V3f&)>& sample,
                                   const std::function<double(const V3f&)>& pdf,
                                   double cosThetaMin, int thetaBins, int phiBins,
                                   int sampleCount, uint64_t seed, double significance) {
    const double zMin = std::clamp(cosThetaMin, -1.0, 1.0 - 1e-9);
    const bool hasBelow = zMin > -1.0;
    const int capCells = thetaBins * phiBins;
    const int below = capCells;  // index of the "below the cap" category
    std::vector<int64_t> counts(size_t(capCells + (hasBelow ? 1 : 0)), 0);
    int64_t failed = 0, invalid = 0;
    Rng rng(hashSeed(seed, 0x5eed), hashSeed(seed, 1));
    const double dz = (1.0 - zMin) / thetaBins;
    for (int i = 0; i < sampleCount; ++i) {
        V3f w;
        if (!sample(rng, w)) {
            ++failed;
            continue;
        }
        const double len = std::sqrt(double(w.x) * w.x + double(w.y) * w.y + double(w.z) * w.z);
        if (!std::isfinite(len) || std::abs(len - 1.0) > 1e-3) {
            ++invalid;
            continue;
        }
        const double z = std::clamp(w.z / len, -1.0, 1.0);
        if (z < zMin) {
            ++counts[size_t(below)];
            continue;
        }
        double phi = std::atan2(double(w.y), double(w.x));
        if (phi < 0.0) phi += kTwoPi;
        const int ti = std::clamp(int((z - zMin) / dz), 0, thetaBins - 1);
        const int pi = std::clamp(int(phi / kTwoPi * phiBins), 0, phiBins - 1);
        ++counts[size_t(ti * phiBins + pi)];
    }

    PdfGuard guard;
    auto g = [&](double z, double phi) { return guard(pdf(sphereDirection(z, phi))); };
    std::vector<double> integral(counts.size(), 0.0);
    for (int ti = 0; ti < thetaBins; ++ti) {
        const double z0 = zMin + ti * dz, z1 = (ti + 1 == thetaBins) ? 1.0 : zMin + (ti + 1) * dz;
        for (int pi = 0; pi < phiBins; ++pi) {
            const double p0 = kTwoPi * pi / phiBins, p1 = kTwoPi * (pi + 1) / phiBins;
            integral[size_t(ti * phiBins + pi)] = integrate2D(g, z0, z1, p0, p1);
        }
    }
    if (hasBelow) {
        // Below the cap: one category, integrated on a grid as fine as a full-sphere test's.
        const int zCells = std::max(8, int(std::ceil((zMin + 1.0) / 0.05)));
        const double bz = (zMin + 1.0) / zCells;
        double sum = 0.0;
        for (int ti = 0; ti < zCells; ++ti) {
            const double z0 = -1.0 + ti * bz, z1 = (ti + 1 == zCells) ? zMin : -1.0 + (ti + 1) * bz;
            for (int pi = 0; pi < 32; ++pi)
                sum += integrate2D(g, z0, z1, kTwoPi * pi / 32, kTwoPi * (pi + 1) / 32);
        }
        integral[size_t(below)] = sum;
    }
    auto describe = [&](int cell) {
        if (cell == below) return fmt("below the cap (cos(theta) < %.4f)", zMin);
        const int ti = cell / phiBins, pi = cell % phiBins;
        return fmt("cos(theta) in [%.4f, %.4f], phi in [%.1f, %.1f] deg", zMin + ti * dz,
                   zMin + (ti + 1) * dz, 360.0 * pi / phiBins, 360.0 * (pi + 1) / phiBins);
    };
    return evaluate(integral, counts, sampleCount, failed, 0, invalid, guard.bad, significance,
                    describe);
}

ChiSquareResult chiSquareRect(const std::function<bool(Rng&, V2f&)>& sample,
                              const std::function<double(const V2f&)>& pdf, const V2f& lo,
                              const V2f& hi, int xBins, int yBins, int sampleCount, uint64_t seed,
                              double significance) {
    const int cells = xBins * yBins;
    std::vector<int64_t> counts(size_t(cells), 0);
    int64_t failed = 0, invalid = 0, offDomain = 0;
    Rng rng(hashSeed(seed, 0x5eed), hashSeed(seed, 1));
    const double dx = (double(hi.x) - lo.x) / xBins, dy = (double(hi.y) - lo.y) / yBins;
    for (int i = 0; i < sampleCount; ++i) {
        V2f p;
        if (!sample(rng, p)) {
            ++failed;
            continue;
        }
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            ++invalid;
            continue;
        }
        if (p.x < lo.x || p.x > hi.x || p.y < lo.y || p.y > hi.y) {
            ++offDomain;
            continue;
        }
        const int xi = std::clamp(int((p.x - double(lo.x)) / dx), 0, xBins - 1);
        const int yi = std::clamp(int((p.y - double(lo.y)) / dy), 0, yBins - 1);
        ++counts[size_t(yi * xBins + xi)];
    }

    PdfGuard guard;
    auto g = [&](double y, double x) { return guard(pdf(V2f(float(x), float(y)))); };
    std::vector<double> integral(static_cast<size_t>(cells), 0.0);
    for (int yi = 0; yi < yBins; ++yi)
        for (int xi = 0; xi < xBins; ++xi)
            integral[size_t(yi * xBins + xi)] =
                integrate2D(g, lo.y + yi * dy, lo.y + (yi + 1) * dy, lo.x + xi * dx,
                            lo.x + (xi + 1) * dx);
    auto describe = [&](int cell) {
        const int yi = cell / xBins, xi = cell % xBins;
        return fmt("x in [%.4f, %.4f], y in [%.4f, %.4f]", lo.x + xi * dx, lo.x + (xi + 1) * dx,
                   lo.y + yi * dy, lo.y + (yi + 1) * dy);
    };
    return evaluate(integral, counts, sampleCount, failed, offDomain, invalid, guard.bad,
                    significance, describe);
}

double integrateOverSphere(const std::function<double(const V3f&)>& f, int thetaBins, int phiBins) {
    auto g = [&](double z, double phi) { return f(sphereDirection(z, phi)); };
    double sum = 0.0;
    for (int ti = 0; ti < thetaBins; ++ti) {
        const double z0 = -1.0 + 2.0 * ti / thetaBins, z1 = -1.0 + 2.0 * (ti + 1) / thetaBins;
        for (int pi = 0; pi < phiBins; ++pi)
            sum += integrate2D(g, z0, z1, kTwoPi * pi / phiBins, kTwoPi * (pi + 1) / phiBins);
    }
    return sum;
}

}  // namespace lucerna
