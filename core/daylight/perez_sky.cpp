#include "core/daylight/perez_sky.h"

#include "core/daylight/hemisphere_quadrature.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {

constexpr double kPiD = std::numbers::pi;
constexpr double kDeg = kPiD / 180.0;

// ../shared/data/perez.txt, row by row (tests/core/test_perez_sky.cpp checks them against it).
constexpr double kClearnessUpper[8] = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200, 12.010};
constexpr double kLuminance[8][20] = {
    {1.3525, -0.2576, -0.2690, -1.4366, -0.7670, 0.0007, 1.2734, -0.1233, 2.8000, 0.6004, 1.2375, 1.0000, 1.8734, 0.6297, 0.9738, 0.2809, 0.0356, -0.1246, -0.5718, 0.9938},
    {-1.2219, -0.7730, 1.4148, 1.1016, -0.2054, 0.0367, -3.9128, 0.9156, 6.9750, 0.1774, 6.4477, -0.1239, -1.5798, -0.5081, -1.7812, 0.1080, 0.2624, 0.0672, -0.2190, -0.4285},
    {-1.1000, -0.2515, 0.8952, 0.0156, 0.2782, -0.1812, -4.5000, 1.1766, 24.7219, -13.0812, -37.7000, 34.8438, -5.0000, 1.5218, 3.9229, -2.6204, -0.0156, 0.1597, 0.4199, -0.5562},
    {-0.5484, -0.6654, -0.2672, 0.7117, 0.7234, -0.6219, -5.6812, 2.6297, 33.3389, -18.3000, -62.2500, 52.0781, -3.5000, 0.0016, 1.1477, 0.1062, 0.4659, -0.3296, -0.0876, -0.0329},
    {-0.6000, -0.3566, -2.5000, 2.3250, 0.2937, 0.0496, -5.6812, 1.8415, 21.0000, -4.7656, -21.5906, 7.2492, -3.5000, -0.1554, 1.4062, 0.3988, 0.0032, 0.0766, -0.0656, -0.1294},
    {-1.0156, -0.3670, 1.0078, 1.4051, 0.2875, -0.5328, -3.8500, 3.3750, 14.0000, -0.9999, -7.1406, 7.5469, -3.4000, -0.1078, -1.0750, 1.5702, -0.0672, 0.4016, 0.3017, -0.4844},
    {-1.0000, 0.0211, 0.5025, -0.5119, -0.3000, 0.1922, 0.7023, -1.6317, 19.0000, -5.0000, 1.2438, -1.9094, -4.0000, 0.0250, 0.3844, 0.2656, 1.0468, -0.3788, -2.4517, 1.4656},
    {-1.0500, 0.0289, 0.4260, 0.3590, -0.3250, 0.1156, 0.7781, 0.0025, 31.0625, -14.5000, -46.1148, 55.3750, -7.2312, 0.4050, 13.3500, 0.6234, 1.5000, -0.6426, 1.8564, 0.5636},
};
constexpr double kDiffuseEfficacy[8][4] = {
    {97.24, -0.46, 12.00, -8.91},    {107.22, 1.15, 0.59, -3.95},     {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90},  {100.71, 5.94, -22.75, -23.74},  {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03},  {152.23, 0.35, -45.27, -7.98}};
constexpr double kDirectEfficacy[8][4] = {
    {57.20, -4.55, -2.98, 117.12},   {98.99, -3.46, -1.21, 12.38},    {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56},   {106.36, -3.97, -1.75, -6.16},   {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44},   {101.18, 1.58, -1.10, -8.29}};

int clearnessCategory(double epsilon) {
    for (int k = 0; k < 8; ++k)
        if (epsilon < kClearnessUpper[k]) return k + 1;
    return 8;
}

PerezCoefficients luminanceCoefficients(int category, double z, double delta) {
    const double* x = kLuminance[category - 1];
    const auto term = [&](int i) { return x[i] + x[i + 1] * z + delta * (x[i + 2] + x[i + 3] * z); };
    PerezCoefficients k{term(0), term(4), term(8), term(12), term(16)};
    if (category == 1) {
        k.c = std::exp(std::pow(delta * (x[8] + x[9] * z), x[10])) - x[11];
        k.d = -std::exp(delta * (x[12] + x[13] * z)) + x[14] + delta * x[15];
    }
    return k;
}

}  // namespace

int dayOfYear(int year, int month, int day) {
    static constexpr int kBefore[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return kBefore[std::clamp(month, 1, 12) - 1] + day + (leap && month > 2 ? 1 : 0);
}

PerezSky::PerezSky(const PerezInputs& in, int integralResolution) {
    const double ib = std::max(in.directNormalIrradiance, 0.0), ed = std::max(in.diffuseHorizontalIrradiance, 0.0);
    const V3d toward = in.towardSun.normalized();
    const bool sunUp = toward.y > 0;
    // SPEC.md: Z is 90 degrees for a sun at or below the horizon and at least 3 degrees, for the
    // model's inputs and the direction gamma is measured from.
    const double trueZenith = std::acos(std::clamp(toward.y, -1.0, 1.0));
    zenith_ = sunUp ? std::max(trueZenith, 3 * kDeg) : kPiD / 2;
    V3d horizontal(toward.x, 0, toward.z);
    horizontal = horizontal.length() > 0 ? horizontal.normalized() : V3d(1, 0, 0);
    towardSun_ = horizontal * std::sin(zenith_) + V3d(0, std::cos(zenith_), 0);

    const double zDeg = zenith_ / kDeg, cosZ = std::cos(zenith_);
    const double airMass = 1.0 / (cosZ + 0.15 * std::pow(93.885 - zDeg, -1.253));
    const double t = 2 * kPiD * (in.dayOfYear - 1) / 365.0;
    const double e0 = 1.00011 + 0.034221 * std::cos(t) + 0.00128 * std::sin(t) + 0.000719 * std::cos(2 * t) +
                      0.000077 * std::sin(2 * t);
    const double z3 = 1.041 * zenith_ * zenith_ * zenith_;
    epsilon_ = ed > 0 ? std::min(((ed + ib) / ed + z3) / (1 + z3), 11.9) : 11.9;
    delta_ = std::max(ed * airMass / (1367 * e0), 0.01);
    category_ = clearnessCategory(epsilon_);
    const double water = std::exp(0.07 * in.dewPointC - 0.075);  // precipitable water, cm

    const double* kd = kDiffuseEfficacy[category_ - 1];
    const double* kn = kDirectEfficacy[category_ - 1];
    // The diffuse efficacy stays positive for any real hour; the guard keeps a freak row from
    // making a negative sky.
    evd_ = ed * std::max(0.0, kd[0] + kd[1] * water + kd[2] * cosZ + kd[3] * std::log(delta_));
    evn_ = sunUp ? ib * std::max(0.0, kn[0] + kn[1] * water + kn[2] * std::exp(5.73 * zenith_ - 5) + kn[3] * delta_) : 0;

    const double deltaForShape = epsilon_ > 1.065 && epsilon_ < 2.8 ? std::max(delta_, 0.2) : delta_;
    k_ = luminanceCoefficients(category_, zenith_, deltaForShape);
    // Shape only (resolution 0): a coarse integral still tells the all-negative sky that falls
    // back to uniform.
    const double integral = horizontalIntegral(integralResolution > 0 ? integralResolution : 16);
    uniform_ = !(integral > 0);
    if (integralResolution > 0 && evd_ > 0) scale_ = uniform_ ? evd_ / kPiD : evd_ / integral;
}

double PerezSky::lvUnclamped(double cosZeta, double gamma) const {
    const double cosZetaClamped = std::max(cosZeta, std::cos(84 * kDeg));  // zeta' = min(zeta, 84 deg)
    const double cg = std::cos(gamma);
    return (1 + k_.a * std::exp(k_.b / cosZetaClamped)) * (1 + k_.c * std::exp(k_.d * gamma) + k_.e * cg * cg);
}

double PerezSky::relativeLuminance(const V3d& w) const {
    if (!(w.y > 0)) return 0;
    if (uniform_) return 1;
    const double gamma = std::acos(std::clamp(w.dot(towardSun_), -1.0, 1.0));
    return std::max(lvUnclamped(w.y, gamma), 0.0);
}

double PerezSky::horizontalIntegral(int resolution) const {
    return lucerna::horizontalIntegral(
        [&](const V3d& w) { return std::max(lvUnclamped(w.y, std::acos(std::clamp(w.dot(towardSun_), -1.0, 1.0))), 0.0); },
        resolution);
}

}  // namespace lucerna
