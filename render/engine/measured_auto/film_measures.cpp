#include "render/engine/measured_auto/film_measures.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <tbb/parallel_for.h>

namespace lucerna {

namespace {

double channel(const Rgb& c, int i) { return i == 0 ? c.x : (i == 1 ? c.y : c.z); }

// Per tile: the mean of `a` and of the squared differences (a - b)^2 / 4 over pixels and
// channels, and the squared difference of the tile means of a and b over 4. With a and b two
// independent estimates of equal variance, the last two are the variances of one value and of
// the tile mean of (a + b) / 2. With a reference, also the squared differences over 4 each by
// SPEC's denominator of its reference value.
struct DifferenceSums {
    std::vector<double> meanA, meanB, halfDifference2, relativeHalfDifference2, values;
};
DifferenceSums differences(const Image& a, const Image& b, const TileGrid& tiles, const Image* reference) {
    DifferenceSums s;
    const size_t n = size_t(tiles.count());
    s.meanA.assign(n, 0.0), s.meanB.assign(n, 0.0), s.halfDifference2.assign(n, 0.0), s.values.assign(n, 0.0);
    if (reference) s.relativeHalfDifference2.assign(n, 0.0);
    for (int y = 0; y < tiles.height; ++y)
        for (int x = 0; x < tiles.width; ++x) {
            const size_t t = size_t(tiles.of(x, y));
            for (int c = 0; c < 3; ++c) {
                const double va = channel(a.at(x, y), c), vb = channel(b.at(x, y), c);
                if (!std::isfinite(va) || !std::isfinite(vb)) continue;
                const double d2 = 0.25 * (va - vb) * (va - vb);
                s.meanA[t] += va, s.meanB[t] += vb, s.halfDifference2[t] += d2;
                if (reference) s.relativeHalfDifference2[t] += d2 / relmseDenominator(channel(reference->at(x, y), c));
                s.values[t] += 1;
            }
        }
    for (size_t t = 0; t < n; ++t) {
        if (!(s.values[t] > 0)) continue;
        s.meanA[t] /= s.values[t], s.meanB[t] /= s.values[t], s.halfDifference2[t] /= s.values[t];
        if (reference) s.relativeHalfDifference2[t] /= s.values[t];
    }
    return s;
}

// Stats of (a + b) / 2 as an estimate: its tile mean, its variance per value, and the variance
// of its tile mean (from the tile means' difference, at least the per-value variance over the
// values: pixels whose errors correlate, as a VPL set's or a chain's do, make it larger).
TileStats statsOf(const DifferenceSums& d, double scale, std::span<const double> mean) {
    TileStats s;
    s.mean.assign(mean.begin(), mean.end());
    s.variance.resize(d.values.size());
    s.meanVariance.resize(d.values.size());
    for (double r : d.relativeHalfDifference2) s.relativeVariance.push_back(scale * r);
    for (size_t t = 0; t < d.values.size(); ++t) {
        s.variance[t] = scale * d.halfDifference2[t];
        const double m = 0.5 * (d.meanA[t] - d.meanB[t]);
        s.meanVariance[t] = scale * std::max(m * m, d.halfDifference2[t] / std::max(1.0, d.values[t]));
    }
    return s;
}

double lowerMedian(std::vector<double> v) {
    if (v.empty()) return 0;
    const size_t k = (v.size() - 1) / 2;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

// The median; of an even count, the mean of the middle two.
double median(std::vector<double> v) {
    if (v.empty()) return 0;
    const size_t k = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    if (v.size() % 2) return v[k];
    return 0.5 * (v[k] + *std::max_element(v.begin(), v.begin() + std::ptrdiff_t(k)));
}

// Per method and tile, the squared distance of its tile mean from the other methods' that their
// variances do not explain: the lower median of the distances to each other method.
std::vector<std::vector<double>> unexplainedDistances(std::span<const TileStats* const> methods) {
    const size_t k = methods.size(), n = methods[0]->mean.size();
    std::vector<std::vector<double>> e(k, std::vector<double>(n, 0.0));
    std::vector<double> distances;
    for (size_t i = 0; i < k; ++i)
        for (size_t t = 0; t < n; ++t) {
            distances.clear();
            for (size_t j = 0; j < k; ++j) {
                if (j == i) continue;
                const double d = methods[i]->mean[t] - methods[j]->mean[t];
                distances.push_back(std::max(0.0, d * d - 3.0 * (methods[i]->meanVariance[t] + methods[j]->meanVariance[t])));
            }
            e[i][t] = lowerMedian(distances);
        }
    return e;
}

}  // namespace

TileGrid::TileGrid(int width, int height, int size)
    : width(width), height(height), size(std::max(1, size)), nx((width + this->size - 1) / this->size),
      ny((height + this->size - 1) / this->size) {}

Image medianImage(std::span<const Image* const> images) {
    Image out(images[0]->width, images[0]->height);
    tbb::parallel_for(0, out.height, [&](int y) {
        std::vector<double> v;
        for (int x = 0; x < out.width; ++x) {
            double c[3];
            for (int i = 0; i < 3; ++i) {
                v.clear();
                for (const Image* image : images)
                    if (const double value = channel(image->at(x, y), i); std::isfinite(value)) v.push_back(value);
                c[i] = median(v);
            }
            out.at(x, y) = Rgb(float(c[0]), float(c[1]), float(c[2]));
        }
    });
    return out;
}

MethodMeasure measureMethod(const std::array<ReplicaImages, 2>& replicas, const TileGrid& tiles, bool withHalves,
                            double samples0, double samples1, const Image* reference) {
    MethodMeasure m;
    const DifferenceSums across = differences(replicas[0].image, replicas[1].image, tiles, reference);
    // With per-sample variance s^2, (a - b)^2 estimates s^2 (1/n0 + 1/n1) and the mean by samples
    // has variance s^2 / (n0 + n1): a ratio of n0 n1 / (n0 + n1)^2, a quarter for equal replicas
    // (what `differences` took).
    const double n = samples0 + samples1, f0 = samples0 / n, f1 = samples1 / n;
    std::vector<double> pairMean(across.meanA.size());
    for (size_t t = 0; t < pairMean.size(); ++t) pairMean[t] = f0 * across.meanA[t] + f1 * across.meanB[t];
    m.pair = statsOf(across, 4 * f0 * f1, pairMean);
    m.allocation = m.pair;
    // Replica 0's halves, once for the allocation and the weights.
    std::array<DifferenceSums, 2> within;
    if (replicas[0].bothHalves || withHalves)
        within[0] = differences(replicas[0].half[0], replicas[0].half[1], tiles, reference);
    if (reference && replicas[0].bothHalves) {
        // Replica 0's image has the variance (h0 - h1)^2 / 4 of its halves' difference; as the
        // pair's mean by samples, with error as 1 / samples, f0 times that.
        const TileStats own = statsOf(within[0], f0, pairMean);
        m.allocation.variance = own.variance;
        m.allocation.relativeVariance = own.relativeVariance;
    }
    if (!withHalves) return m;

    double acrossSum = 0, withinSum = 0;
    within[1] = differences(replicas[1].half[0], replicas[1].half[1], tiles, nullptr);
    for (size_t t = 0; t < across.values.size(); ++t) {
        // (a - b)^2 estimates the sum of the replicas' variances, the halves each replica's.
        acrossSum += 4.0 * across.halfDifference2[t] * across.values[t];
        withinSum += (within[0].halfDifference2[t] + within[1].halfDifference2[t]) * across.values[t];
    }
    m.inflation = withinSum > 0 ? std::clamp(acrossSum / withinSum, 1.0, 1000.0) : 1.0;
    for (int r = 0; r < 2; ++r) {
        const std::vector<double>& mean = r == 0 ? across.meanA : across.meanB;
        m.replica[size_t(r)] = statsOf(within[r], m.inflation, mean);
    }
    return m;
}

namespace {
// What a tile's squared errors are taken relative to: SPEC's denominator of its mean over the
// methods (relmseDenominator), so that the weights' errors weigh a tile as the relmse does. Most
// members are dim (the images' means 0.05 to 0.19), where the relmse's 0.01 outweighs r^2: relative
// to the squared brightness alone, the dark tiles weighed the most, and a method good on the
// bright ones lost them too, its error there drawn halfway to its mean over the image (the
// daylit deep-plan room: path and mir, level alone, shared the time and the image weighed mir
// 0.73 where their errors asked for 0.44; BENCHMARKS.md, R106).
std::vector<double> tileDenominators(std::span<const TileStats* const> methods) {
    const size_t k = methods.size(), n = methods[0]->mean.size();
    std::vector<double> denominators(n, 0.0);
    for (size_t t = 0; t < n; ++t) {
        double mean = 0;
        for (const TileStats* m : methods) mean += std::abs(m->mean[t]) / double(k);
        denominators[t] = relmseDenominator(mean);
    }
    return denominators;
}
}  // namespace

std::vector<double> relativeErrors(std::span<const TileStats* const> methods,
                                   const std::vector<std::vector<double>>& errors) {
    std::vector<double> r(methods.size(), 0.0);
    if (methods.empty()) return r;
    const std::vector<double> denominators = tileDenominators(methods);
    const size_t n = denominators.size();
    for (size_t i = 0; i < methods.size(); ++i)
        for (size_t t = 0; t < n; ++t) r[i] += errors[i][t] / denominators[t] / double(n);
    return r;
}

double errorLevelRatio(const TileStats& a, const TileStats& b) {
    const std::array<const TileStats*, 2> both{&a, &b};
    const std::vector<double> level = relativeErrors(both, {a.variance, b.variance});
    return level[1] > 0 ? level[0] / level[1] : 0.0;
}

std::vector<std::vector<double>> measuredSquaredErrors(std::span<const TileStats* const> methods) {
    if (methods.empty()) return {};
    std::vector<std::vector<double>> e = unexplainedDistances(methods);
    for (size_t i = 0; i < e.size(); ++i)
        for (size_t t = 0; t < e[i].size(); ++t) e[i][t] += methods[i]->variance[t];
    return e;
}

std::vector<std::vector<double>> relativeSquaredErrors(std::span<const TileStats* const> methods) {
    if (methods.empty()) return {};
    std::vector<std::vector<double>> e = unexplainedDistances(methods);
    std::vector<double> means(methods.size());
    for (size_t t = 0; t < e[0].size(); ++t) {
        for (size_t i = 0; i < methods.size(); ++i) means[i] = methods[i]->mean[t];
        const double denominator = relmseDenominator(median(means));
        for (size_t i = 0; i < e.size(); ++i) {
            const TileStats& m = *methods[i];
            e[i][t] = e[i][t] / denominator + (m.relativeVariance.empty() ? m.variance[t] / denominator : m.relativeVariance[t]);
        }
    }
    return e;
}

std::vector<std::vector<double>> expectedSquaredErrors(std::span<const TileStats* const> methods,
                                                       std::span<const double> floors) {
    std::vector<std::vector<double>> e = measuredSquaredErrors(methods);
    if (e.empty()) return e;
    const std::vector<double> denominators = tileDenominators(methods);
    const size_t n = denominators.size();
    for (size_t i = 0; i < e.size(); ++i) {
        std::vector<double> relative(n);
        double mean = 0;
        for (size_t t = 0; t < n; ++t) relative[t] = e[i][t] / denominators[t], mean += relative[t] / double(n);
        const double floor = std::max(0.25 * lowerMedian(relative), floors.empty() ? 0.0 : floors[i]);
        for (size_t t = 0; t < n; ++t)
            e[i][t] = std::max(std::sqrt(relative[t] * mean), floor) * denominators[t];
    }
    return e;
}

std::vector<std::vector<double>> inverseErrorWeights(const std::vector<std::vector<double>>& errors, double minimum) {
    std::vector<std::vector<double>> w = errors;
    if (errors.empty()) return w;
    for (size_t t = 0; t < errors[0].size(); ++t) {
        bool anyZero = false;
        for (const auto& e : errors) anyZero = anyZero || !(e[t] > 0);
        const auto normalise = [&] {
            double sum = 0;
            for (auto& wk : w) sum += wk[t];
            for (auto& wk : w) wk[t] /= sum;
        };
        // A zero error (every method saw the same constant, or black) weighs like the others.
        for (size_t k = 0; k < errors.size(); ++k) w[k][t] = anyZero ? 1.0 : 1.0 / errors[k][t];
        normalise();
        if (anyZero) continue;
        for (auto& wk : w)
            if (wk[t] < minimum) wk[t] = 0;  // the largest weight is at least 1 / K, never dropped
        normalise();
    }
    return w;
}

Image combineImages(std::span<const Image* const> images, const std::vector<std::vector<double>>& weights,
                    const TileGrid& tiles) {
    Image out(tiles.width, tiles.height);
    // The tile coordinate of a pixel centre: tile i's centre is at i + 0.5 tiles.
    const auto axis = [&](int p, int count, int& i0, int& i1, double& f) {
        const double u = std::clamp((p + 0.5) / tiles.size - 0.5, 0.0, double(count - 1));
        i0 = int(u), i1 = std::min(i0 + 1, count - 1), f = u - i0;
    };
    for (int y = 0; y < tiles.height; ++y) {
        int y0, y1;
        double fy;
        axis(y, tiles.ny, y0, y1, fy);
        for (int x = 0; x < tiles.width; ++x) {
            int x0, x1;
            double fx;
            axis(x, tiles.nx, x0, x1, fx);
            const size_t t00 = size_t(y0 * tiles.nx + x0), t01 = size_t(y0 * tiles.nx + x1);
            const size_t t10 = size_t(y1 * tiles.nx + x0), t11 = size_t(y1 * tiles.nx + x1);
            Rgb sum(0, 0, 0);
            for (size_t k = 0; k < images.size(); ++k) {
                const auto& w = weights[k];
                const double wk = (1 - fy) * ((1 - fx) * w[t00] + fx * w[t01]) + fy * ((1 - fx) * w[t10] + fx * w[t11]);
                sum += images[k]->at(x, y) * float(wk);
            }
            out.at(x, y) = sum;
        }
    }
    return out;
}

std::vector<std::vector<double>> pooledTowardMean(const std::vector<std::vector<double>>& errors) {
    std::vector<std::vector<double>> pooled = errors;
    for (auto& e : pooled) {
        const double mean = std::accumulate(e.begin(), e.end(), 0.0) / double(e.size());
        for (double& x : e) x = 0.5 * (x + mean);
    }
    return pooled;
}

std::vector<double> marginalGains(const std::vector<std::vector<double>>& errors, std::span<const double> costs) {
    std::vector<double> g(errors.size(), 0.0);
    if (errors.empty()) return g;
    for (size_t t = 0; t < errors[0].size(); ++t) {
        double precision = 0;
        for (const auto& e : errors) precision += e[t] > 0 ? 1.0 / e[t] : 0.0;
        if (!(precision > 0)) continue;
        const double v = 1.0 / precision;
        for (size_t k = 0; k < errors.size(); ++k)
            if (errors[k][t] > 0 && costs[k] > 0) g[k] += v * v / (errors[k][t] * costs[k]);
    }
    return g;
}

}  // namespace lucerna
