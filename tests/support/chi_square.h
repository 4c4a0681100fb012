#pragma once
// Pearson chi-square goodness-of-fit tests for samplers (after Nori's and Mitsuba's warptest):
// draw samples, histogram them, integrate the claimed density over every histogram cell, and ask
// how likely the observed counts are if the sampler really draws from that density.
//
// What a pass means: the sampler's distribution and the claimed pdf agree to within what
// sampleCount samples can resolve. It checks the pdf *as a density*, normalisation included:
// a sampler that may fail (returns false) must be described by a sub-normalised pdf whose
// integral is the success probability; failures form their own histogram category.
//
// Usage in Qt tests:
//   const auto r = chiSquareSphere(sampler, pdf, 20, 40, 1'000'000, seed, 0.01 / kNumTests);
//   QVERIFY2(r.passed, r.message.c_str());
//
// Everything is deterministic for a given seed; the cost is O(sampleCount) plus the numerical
// integration (nested adaptive Simpson per cell, to 1e-6 relative; about 200 pdf calls per cell
// for a smooth pdf). The integration starts from 4 x 4 panels per cell: a feature of the pdf
// narrower than about 1/8 of a cell and away from the cell's edges can be missed, so give peaked
// densities enough cells (or use chiSquareSphereCap around the peak). The pdf is called on
// directions and points rounded to float; integration-point ties at cell edges are harmless.

#include "core/math.h"
#include "render/trace/rng.h"

#include <cstdint>
#include <functional>
#include <string>

namespace lucerna {

struct ChiSquareResult {
    bool passed = false;
    double statistic = 0;     // Pearson's X^2 over the pooled categories
    int degreesOfFreedom = 0; // categories after pooling - 1
    double pValue = 0;        // P(X^2 >= statistic) under the hypothesis
    double significance = 0;  // the threshold it was held to
    double pdfIntegral = 0;   // integral of the claimed pdf over the whole domain
    int64_t samples = 0;      // attempts
    int64_t failedSamples = 0;   // sample() returned false
    int64_t strayedSamples = 0;  // landed in cells where the pdf integrates to 0 (or off-domain)
    int pooledCells = 0;         // cells merged into the low-expectation pool
    std::string message;  // why it failed (with the worst cells); on success a one-line summary
};

// Samples directions on the unit sphere. sample(rng, w) draws one direction into w (unit) or
// returns false for a failed attempt; pdf(w) is the claimed solid-angle density (>= 0; may be
// sub-normalised when samples can fail). The sphere is cut into thetaBins cells of equal
// cos(theta) (z from -1 to 1, so even thetaBins put the horizon on a cell edge) times phiBins
// cells of equal phi. Fails when the p-value is below `significance`, when the pdf integrates to
// more than 1 (+1e-3 integration slack), when more than 1e-5 of the samples land where the pdf
// integrates to zero, or when a sample is not a finite unit vector.
ChiSquareResult chiSquareSphere(const std::function<bool(Rng&, V3f&)>& sample,
                                const std::function<double(const V3f&)>& pdf, int thetaBins,
                                int phiBins, int sampleCount, uint64_t seed,
                                double significance = 0.01);

// Like chiSquareSphere, but only the cap z >= cosThetaMin is cut into thetaBins x phiBins cells
// (of equal solid angle); everything below it is one category. For peaked densities (narrow
// cones, GGX at small alpha) whose mass would otherwise fall into one or two cells.
ChiSquareResult chiSquareSphereCap(const std::function<bool(Rng&, V3f&)>& sample,
                                   const std::function<double(const V3f&)>& pdf,
                                   double cosThetaMin, int thetaBins, int phiBins,
                                   int sampleCount, uint64_t seed, double significance = 0.01);

// The same on the rectangle [lo, hi] of the plane (for a square, a disk or triangle barycentrics
// embedded in one): pdf(p) is the claimed density per unit area, 0 off its support. Samples
// outside the rectangle count as strays.
ChiSquareResult chiSquareRect(const std::function<bool(Rng&, V2f&)>& sample,
                              const std::function<double(const V2f&)>& pdf, const V2f& lo,
                              const V2f& hi, int xBins, int yBins, int sampleCount, uint64_t seed,
                              double significance = 0.01);

// Integral of f over the unit sphere (per steradian), with the same cell-wise adaptive Simpson
// integration the tests use; good to ~1e-6 relative for the pdfs in this code base. For white
// furnace tests: integrateOverSphere([&](V3f w){ return f(wo, w) * |w.z|; }).
double integrateOverSphere(const std::function<double(const V3f&)>& f, int thetaBins = 32,
                           int phiBins = 64);

// Upper regularised incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a), a > 0, x >= 0.
double regularizedGammaQ(double a, double x);

// P(X >= statistic) for X chi-square distributed with dof degrees of freedom.
inline double chiSquarePValue(double statistic, int dof) {
    return regularizedGammaQ(0.5 * dof, 0.5 * statistic);
}

}  // namespace lucerna
