#include "render/preview/daylight_samples.h"

#include "render/trace/rng.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {

constexpr double kPiD = std::numbers::pi;

// An orthonormal pair perpendicular to unit a.
void perpendicular(const V3d& a, V3d& s, V3d& t) {
    s = (std::abs(a.x) < 0.9 ? V3d(1, 0, 0) : V3d(0, 1, 0)).cross(a).normalized();
    t = a.cross(s);
}

// The equal-area sphere: y = 1 - 2u, phi = 2 pi v (uniform (u, v): uniform directions).
V3d sphereDirection(double u, double v) {
    const double y = std::clamp(1.0 - 2.0 * u, -1.0, 1.0), r = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double phi = 2.0 * kPiD * v;
    return V3d(r * std::cos(phi), y, r * std::sin(phi));
}

// Finds the bin of x in a cumulative table cdf[0] = 0 .. cdf[n] = 1 and the offset within it.
size_t findBin(const std::vector<double>& cdf, double x, double& within) {
    const size_t n = cdf.size() - 1;
    size_t i = size_t(std::upper_bound(cdf.begin(), cdf.end(), x) - cdf.begin());
    i = std::clamp<size_t>(i, 1, n) - 1;
    while (i + 1 < n && cdf[i + 1] - cdf[i] <= 0) ++i;  // never an empty bin
    const double width = cdf[i + 1] - cdf[i];
    within = width > 0 ? std::clamp((x - cdf[i]) / width, 0.0, 1.0 - 1e-12) : 0.5;
    return i;
}

std::vector<double> cumulative(const double* weights, size_t n) {
    std::vector<double> cdf(n + 1, 0.0);
    for (size_t i = 0; i < n; ++i) cdf[i + 1] = cdf[i] + weights[i];
    const double total = cdf[n];
    for (double& c : cdf) c = total > 0 ? c / total : 0.0;
    return cdf;
}

}  // namespace

std::optional<DirectionalSample> sunSample(const ResolvedSun& sun, uint64_t seed) {
    if (!sun.aboveHorizon || !(sun.illuminanceLux > 0)) return std::nullopt;
    V3d toward = sun.towardSun.normalized();
    if (sun.halfAngleRad > 0) {
        Rng rng(seed, 0x5017ULL);
        // Uniform in the cone: cos theta uniform in [cos(half angle), 1].
        const double oneMinusCosMax = 2.0 * std::pow(std::sin(0.5 * sun.halfAngleRad), 2.0);
        const double oneMinusCos = rng.nextDouble() * oneMinusCosMax;
        const double cosTheta = 1.0 - oneMinusCos, sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
        const double phi = 2.0 * kPiD * rng.nextDouble();
        V3d s, t;
        perpendicular(toward, s, t);
        toward = (toward * cosTheta + s * (sinTheta * std::cos(phi)) + t * (sinTheta * std::sin(phi))).normalized();
    }
    return DirectionalSample{toFloat(toward), toFloat(sun.irradiance())};
}

std::vector<DirectionalSample> skySamples(const ResolvedSky& sky, int count, uint64_t seed) {
    std::vector<DirectionalSample> out;
    if (count <= 0) return out;
    constexpr int rows = kSkyTableRows, columns = 2 * kSkyTableRows;
    // An even row count puts the horizon on a row boundary: no cell mixes sky and ground.
    static_assert(rows % 2 == 0);
    std::vector<double> cell(size_t(rows * columns));
    double halves[2] = {0, 0};  // sky, ground
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            const double l = sky.luminance(sphereDirection((i + 0.5) / rows, (j + 0.5) / columns));
            cell[size_t(i * columns + j)] = l;
            halves[i < rows / 2 ? 0 : 1] += l;
        }
    const double sum = halves[0] + halves[1];
    if (!(sum > 0)) return out;
    // A floor keeps the density positive over every half of the sphere that has light, whatever
    // the cell centres saw (a narrow circumsolar peak), so that the estimate stays unbiased.
    const double floor = 0.01 * sum / double(rows * columns);
    for (int i = 0; i < rows; ++i)
        if (halves[i < rows / 2 ? 0 : 1] > 0)
            for (int j = 0; j < columns; ++j) cell[size_t(i * columns + j)] += floor;
    std::vector<double> rowWeight(size_t(rows), 0.0);
    std::vector<std::vector<double>> columnCdf(static_cast<size_t>(rows));
    for (int i = 0; i < rows; ++i) {
        const double* r = &cell[size_t(i * columns)];
        for (int j = 0; j < columns; ++j) rowWeight[size_t(i)] += r[j];
        columnCdf[size_t(i)] = cumulative(r, size_t(columns));
    }
    const std::vector<double> rowCdf = cumulative(rowWeight.data(), size_t(rows));
    double total = 0;
    for (double w : rowWeight) total += w;
    // Each cell subtends 4 pi / (rows columns) sr: p(w) = (cell / total) rows columns / (4 pi).
    const double cellSolidAngle = 4.0 * kPiD / double(rows * columns);
    Rng rng(seed, 0x5c1eULL);
    const double shiftU = rng.nextDouble(), shiftV = rng.nextDouble();
    constexpr double kGolden = 0.6180339887498949;
    out.reserve(size_t(count));
    for (int k = 0; k < count; ++k) {
        // A randomly shifted Fibonacci lattice: stratified in both dimensions of the table.
        const double u = std::fmod((k + shiftU) / count, 1.0), v = std::fmod(k * kGolden + shiftV, 1.0);
        double du = 0, dv = 0;
        const size_t i = findBin(rowCdf, u, du);
        const size_t j = findBin(columnCdf[i], v, dv);
        const V3d w = sphereDirection((double(i) + du) / rows, (double(j) + dv) / columns);
        const double pdf = cell[i * size_t(columns) + j] / total / cellSolidAngle;
        const double irradiance = sky.luminance(w) / kLumensPerWatt / (double(count) * pdf);
        out.push_back({toFloat(w), Rgb(float(irradiance), float(irradiance), float(irradiance))});
    }
    return out;
}

}  // namespace lucerna
