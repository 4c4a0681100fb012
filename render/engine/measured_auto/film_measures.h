#pragma once
// What auto measures of its candidate methods' films (measured_auto_backend.h): per tile of the
// image, each method's mean, its variance and the error it is expected to carry, and from those
// the weights that combine the methods' films and the gain of giving a method more time.
//
// Every method runs as two independent replicas (own seeds, own VPL sets, chains and
// normalisation). Two kinds of variance come of that:
//   - within: a replica's image against its own halves (even and odd passes). The backends
//     give each half its own chains, VPL sets and normalisation (mir's and the Metropolis
//     backends' chain sets are per half), so the halves are independent; for the weights it is
//     scaled by the method's inflation, the image-wide ratio of `across` to `within`, which is
//     over 1 where a chain's short replica has not settled (a shared error, which no half
//     would show, would also raise it).
//   - across: the difference of the two replicas, honest for every method, but after the
//     pilots replica 1 stays at two passes, so across tells a method's first passes' pace.
//     The allocation reads replica 0's within instead (MethodMeasure::allocation).
// The weights that combine replica r's images are computed from replica 1 - r alone (cross-
// fitting), so that they do not correlate with the values they weigh and the combination of
// consistent methods stays consistent (unbiased where the methods are). Only the inflation, one
// number per method from the whole image, is taken from both.

#include "core/image/image.h"

#include <array>
#include <span>
#include <vector>

namespace lucerna {

// The squares the measures are pooled over (the last row and column may be smaller).
struct TileGrid {
    TileGrid(int width, int height, int size);
    int width, height, size, nx, ny;
    int count() const { return nx * ny; }
    int of(int x, int y) const { return (y / size) * nx + x / size; }
};

// What one replica's film shows: its image and the images of its two halves.
struct ReplicaImages {
    Image image, half[2];
    bool bothHalves = true;  // each half has samples
};

// Per tile, from one set of data (one replica, or the pair): the mean over the tile's pixels and
// channels, the variance of one value, and the variance of the tile's mean. Measured against a
// reference image, also the mean of each value's variance over SPEC's denominator of its
// reference value (relmseDenominator): the tile's share of the relmse, per pixel as SPEC weighs
// it (empty without a reference).
struct TileStats {
    std::vector<double> mean, variance, meanVariance, relativeVariance;
};

// Per tile of a method's pair of replicas.
struct MethodMeasure {
    TileStats pair;                    // of the replicas' mean by samples, from their difference (`across`)
    // From each replica alone, `within` scaled by the inflation; empty while a replica has only
    // one half (one pass).
    std::array<TileStats, 2> replica;
    double inflation = 1;              // across over within, image-wide, in [1, 1000]
    // What the allocation weighs: the pair's means, and the error that replica 0 (the one that
    // runs on) shows at its length, from its own halves, as the pair's by samples. Replica 1
    // stays at a pilot's few passes, so the pair's spread tells a method's error per sample over
    // its first passes only, which is not its pace later: on the Cornell box with a glass block
    // mlt's relmse x seconds grew from 0.025 at 0.3 s to 0.056 at 30 s (paths through the glass
    // met late), path's fell from 0.044 to 0.028 by 4 s. Each half runs its own chains, VPL sets
    // and normalisation, so the halves are independent for every method. The pair's where
    // replica 0 has no second half yet, or without a reference.
    TileStats allocation;
    bool hasReplicaStats() const { return !replica[0].mean.empty(); }
};
// `withHalves`: both replicas have passes in both halves. samples0 and samples1: the replicas'
// samples per pixel, which weigh them in the pair's mean (a chain's replicas may differ).
// `reference`, where given: the image whose values stand for the truth in the pair's
// relativeVariance.
MethodMeasure measureMethod(const std::array<ReplicaImages, 2>& replicas, const TileGrid& tiles, bool withHalves,
                            double samples0 = 1, double samples1 = 1, const Image* reference = nullptr);

// Per pixel and channel, the median of the images' finite values (of an even count, the mean of
// the middle two; 0 where none is finite): a reference for SPEC's denominators that no one
// method's noise moves far. One image or more, all of one size.
Image medianImage(std::span<const Image* const> images);

// What SPEC.md's relmse divides a squared error by where the true value is `mean`.
inline double relmseDenominator(double mean) { return mean * mean + 0.01; }

// Per method and tile, the squared error of one value as measured: its variance plus the squared
// distance of its tile mean from the other methods' that their variances do not explain (a bias
// such as the residual of ir's clamp, or a rare event a short run has not seen: path on a
// caustic shows no variance there). The distance is the lower median of the distances to each
// other method, so that one wrong method does not move the others.
std::vector<std::vector<double>> measuredSquaredErrors(std::span<const TileStats* const> methods);
// The same relative to SPEC's relmse, what the allocation weighs: per method and tile, its
// relativeVariance (a tile's variance over the denominator of its mean where there is none) plus
// the distance over the denominator of the methods' median tile mean. Summed over the tiles,
// divided by their count, an estimate of the method's relmse. Per pixel, because a tile's
// pixels differ: with the tile mean's denominator, bdpt's relmse on the Cornell box with a
// chrome block read 2.9 times its per-pixel value and cmlt's 2.06 times, and auto gave the time
// to cmlt, at 2.5 times bdpt's error alone.
std::vector<std::vector<double>> relativeSquaredErrors(std::span<const TileStats* const> methods);
// measuredSquaredErrors spread for the combination's weights: relative to SPEC's denominators of
// the tiles' means (what the relmse divides by), each tile's error is drawn halfway
// (geometrically) to the method's mean over the image, and floored at a quarter of its median:
// a tile's variance is pooled over its pixels, but a method whose errors correlate across pixels
// (a VPL set, a chain) has few degrees of freedom there, so that a tile's estimate may be ten
// times too small, and a tile where a method has seen nothing yet must not claim it is exact.
// Not for the allocation: the spreading moves error between bright and dark tiles, which SPEC's
// relmse weighs per pixel (when the tiles' errors were relative to their squared brightness, on
// the deep-plan daylit room it put path's relmse at 1.7 times its variance and mir's at 0.76
// times, and auto gave mir 95% of the time where path is the faster).
// `floors`, where given: per method, a further floor on its error relative to the tiles'
// denominators (the image-wide error the replicas' spread shows, where a replica's own halves may
// understate it).
std::vector<std::vector<double>> expectedSquaredErrors(std::span<const TileStats* const> methods,
                                                       std::span<const double> floors = {});
// Per method, its mean error over the tiles relative to their denominators (as the floors above).
std::vector<double> relativeErrors(std::span<const TileStats* const> methods,
                                   const std::vector<std::vector<double>>& errors);

// Replica a's error over replica b's, image-wide: their variances summed over the tiles, each
// tile's over its denominator (as relativeErrors); 0 where b shows none. One number from
// the whole image, so it hardly depends on any one value it weighs.
double errorLevelRatio(const TileStats& a, const TileStats& b);

// Per method and tile, the weights of an inverse-error combination: (1 / e_k) / sum_j (1 / e_j);
// equal where every error is 0. Weights under `minimum` are made 0 and the rest renormalised: a
// method that would take a small weight takes little off the error, but its error estimate,
// from few degrees of freedom, may be far too small, and then its noise comes in whole.
std::vector<std::vector<double>> inverseErrorWeights(const std::vector<std::vector<double>>& errors,
                                                     double minimum = 0);

// The images combined with per-tile weights, interpolated bilinearly between the tiles' centres
// (no seams); at every pixel the weights sum to 1.
Image combineImages(std::span<const Image* const> images, const std::vector<std::vector<double>>& weights,
                    const TileGrid& tiles);

// Per method and tile, its relative squared errors (relativeSquaredErrors) drawn halfway to its
// mean over the tiles: the method's relmse stays as measured, and a tile whose estimate is low
// by chance draws time half as much (raw, on the Cornell box cmlt took two fifths of the time for
// tiles where its pilot looked better than path's, and auto's relmse was 1.7 times path's alone
// over 4 seeds).
std::vector<std::vector<double>> pooledTowardMean(const std::vector<std::vector<double>>& errors);

// Per method, the relmse that one more unit of cost given to it takes off the combination's:
// with relative errors e_k(T) after cost c_k, a unit-cost error s_k(T) = e_k(T) c_k, and the
// combination's V(T) = 1 / sum_k 1/e_k(T) (in a tile every method's errors share the
// denominators, so inverse-variance weighting holds relative),
//   g_k = -dJ/dc_k = sum_T V(T)^2 / s_k(T),   J = sum_T V(T).
// Efficiency-aware allocation in the spirit of Grittmann et al. 2022, here across independent
// films.
std::vector<double> marginalGains(const std::vector<std::vector<double>>& errors, std::span<const double> costs);

}  // namespace lucerna
