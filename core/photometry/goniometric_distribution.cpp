#include "core/photometry/goniometric_distribution.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The cell [v[i], v[i + 1]] holding x (x within [v.front(), v.back()]) and the fraction across it.
size_t locate(const std::vector<double>& v, double x, double& t) {
    const auto it = std::upper_bound(v.begin(), v.end(), x);
    size_t i = size_t(std::max<std::ptrdiff_t>(it - v.begin(), 1)) - 1;
    i = std::min(i, v.size() - 2);
    t = std::clamp((x - v[i]) / (v[i + 1] - v[i]), 0.0, 1.0);
    return i;
}

}  // namespace

double GoniometricDistribution::intensity(double cDeg, double gammaDeg) const {
    if (gammaAngles.size() < 2 || cAngles.size() < 2) return 0.0;
    if (!(gammaDeg >= gammaAngles.front() && gammaDeg <= gammaAngles.back())) return 0.0;
    double c = std::fmod(cDeg, 360.0);
    if (c < 0) c += 360.0;
    double s = 0, t = 0;
    const size_t i = locate(cAngles, c, s);
    const size_t j = locate(gammaAngles, gammaDeg, t);
    const double a = at(i, j) * (1 - s) + at(i + 1, j) * s;
    const double b = at(i, j + 1) * (1 - s) + at(i + 1, j + 1) * s;
    return a * (1 - t) + b * t;
}

double GoniometricDistribution::cellFlux(size_t c, size_t g) const {
    const double dC = (cAngles[c + 1] - cAngles[c]) * kDeg;
    const double g0 = gammaAngles[g] * kDeg, g1 = gammaAngles[g + 1] * kDeg;
    // Averaged over C (the solid-angle element does not depend on C), the bilinear intensity is
    // a (1 - t) + b t with t = (gamma - g0) / h; integral of sin is F, of t sin is T.
    const double a = 0.5 * (at(c, g) + at(c + 1, g));
    const double b = 0.5 * (at(c, g + 1) + at(c + 1, g + 1));
    const double h = g1 - g0;
    const double F = std::cos(g0) - std::cos(g1);
    const double T = (std::sin(g1) - std::sin(g0)) / h - std::cos(g1);
    return dC * (a * (F - T) + b * T);
}

double GoniometricDistribution::integratedFlux() const {
    double sum = 0;
    for (size_t c = 0; c + 1 < cAngles.size(); ++c)
        for (size_t g = 0; g + 1 < gammaAngles.size(); ++g) sum += cellFlux(c, g);
    return sum;
}

double GoniometricDistribution::downwardFraction() const {
    double down = 0;
    for (size_t c = 0; c + 1 < cAngles.size(); ++c)
        for (size_t g = 0; g + 1 < gammaAngles.size(); ++g)
            if (gammaAngles[g + 1] <= 90) down += cellFlux(c, g);
    return down / integratedFlux();
}

double GoniometricDistribution::maxIntensity() const {
    return candela.empty() ? 0.0 : *std::max_element(candela.begin(), candela.end());
}

double GoniometricDistribution::tiltMultiplier(double angleDeg) const {
    if (tiltAngles.empty()) return 1.0;
    if (tiltAngles.size() == 1 || angleDeg <= tiltAngles.front()) return tiltMultipliers.front();
    if (angleDeg >= tiltAngles.back()) return tiltMultipliers.back();
    double t = 0;
    const size_t i = locate(tiltAngles, angleDeg, t);
    return tiltMultipliers[i] * (1 - t) + tiltMultipliers[i + 1] * t;
}

GoniometricDistribution assembleDistribution(std::vector<CPlane> planes, std::vector<double> gammaAngles,
                                             const std::vector<std::vector<double>>& columns,
                                             const std::string& label) {
    for (const CPlane& p : planes)
        if (!(p.angleDeg >= 0 && p.angleDeg <= 360))
            throw LuminaireFileError(label + ": C angle " + std::to_string(p.angleDeg) + " is outside 0 to 360 degrees");
    std::stable_sort(planes.begin(), planes.end(), [](const CPlane& a, const CPlane& b) { return a.angleDeg < b.angleDeg; });
    planes.erase(std::unique(planes.begin(), planes.end(),
                             [](const CPlane& a, const CPlane& b) { return std::abs(a.angleDeg - b.angleDeg) < 1e-9; }),
                 planes.end());
    if (planes.empty() || planes.front().angleDeg != 0)
        throw LuminaireFileError(label + ": no C plane at 0 degrees");
    if (planes.back().angleDeg != 360) planes.push_back({360.0, planes.front().column});
    GoniometricDistribution d;
    d.gammaAngles = std::move(gammaAngles);
    for (const CPlane& p : planes) {
        d.cAngles.push_back(p.angleDeg);
        const std::vector<double>& col = columns.at(p.column);
        d.candela.insert(d.candela.end(), col.begin(), col.end());
    }
    return d;
}

}  // namespace lucerna
