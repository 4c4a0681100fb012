#pragma once
// What the sampling tests share: one executable's statistical checks held to a 1% chance of a
// false failure together (Bonferroni), their seeds, and a chi-square check that logs its result.

#include "core/math.h"
#include "tests/support/chi_square.h"

#include <QtTest/QtTest>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace lucerna::test {

// Each check is held to 0.01 / tests, so that a correct implementation fails the executable with
// probability below 1% for a random seed; countOk() says whether no more checks ran than that
// (call it in cleanupTestCase(), so the count stays honest when checks are added). The seeds
// follow one another from `firstSeed`, so a run is deterministic.
class StatisticalChecks {
public:
    StatisticalChecks(int tests, uint64_t firstSeed) : tests_(tests), seed_(firstSeed) {}
    double level() const { return 0.01 / tests_; }
    double significance() {
        ++used_;
        return level();
    }
    uint64_t nextSeed() { return ++seed_; }
    bool countOk() const { return used_ <= tests_; }
    QString summary() const {
        return QString("%1 statistical tests ran (budget %2) at significance %3 each").arg(used_).arg(tests_).arg(level());
    }

private:
    int tests_, used_ = 0;
    uint64_t seed_;
};

// Logs a chi-square result under `what` (the test's log shows every statistic, passed or not).
inline void logChi2(const char* what, const ChiSquareResult& r) { qInfo("%s: %s", what, r.message.c_str()); }

// Unit direction at polar angle theta (degrees from +z) and azimuth phi (degrees).
inline V3f direction(double thetaDeg, double phiDeg = 0.0) {
    const double t = thetaDeg * std::numbers::pi / 180.0, p = phiDeg * std::numbers::pi / 180.0;
    return V3f(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t)));
}

}  // namespace lucerna::test

// Logs a chi-square result and fails the test function where it did not pass.
#define VERIFY_CHI2(what, r)                                 \
    do {                                                     \
        lucerna::test::logChi2(what, r);                     \
        QVERIFY2((r).passed, (r).message.c_str());           \
    } while (0)
