#include "core/daylight/sky_model.h"

#include "core/daylight/hemisphere_quadrature.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace lucerna {

CieSkyParameters cieSkyParameters(int type) {
    // SPEC.md section 5 (ISO 15469 table 1): gradation groups, then indicatrix groups.
    static constexpr double kGradation[15][2] = {
        {4, -0.7},  {4, -0.7},  {1.1, -0.8}, {1.1, -0.8}, {0, -1},       {0, -1},        {0, -1},   {0, -1},
        {-1, -0.55}, {-1, -0.55}, {-1, -0.55}, {-1, -0.32}, {-1, -0.32}, {-1, -0.15}, {-1, -0.15}};
    static constexpr double kIndicatrix[15][3] = {
        {0, -1, 0},      {2, -1.5, 0.15}, {0, -1, 0},      {2, -1.5, 0.15}, {0, -1, 0},
        {2, -1.5, 0.15}, {5, -2.5, 0.3},  {10, -3, 0.45},  {2, -1.5, 0.15}, {5, -2.5, 0.3},
        {10, -3, 0.45},  {10, -3, 0.45},  {16, -3, 0.3},   {16, -3, 0.3},   {24, -2.8, 0.15}};
    if (type < 1 || type > 15) throw std::invalid_argument("CIE general sky type must be from 1 to 15");
    const auto& g = kGradation[type - 1];
    const auto& i = kIndicatrix[type - 1];
    return {g[0], g[1], i[0], i[1], i[2]};
}

namespace {

constexpr double kPiD = std::numbers::pi;

double gradation(const CieSkyParameters& p, double cosZ) {
    // b < 0 for every type, so exp(b / cos Z) -> 0 at the horizon and phi -> 1.
    return cosZ <= 0 ? 1.0 : 1.0 + p.a * std::exp(p.b / cosZ);
}

double indicatrix(const CieSkyParameters& p, double chi) {
    const double c = std::cos(chi);
    return 1.0 + p.c * (std::exp(p.d * chi) - std::exp(p.d * kPiD / 2)) + p.e * c * c;
}

double angleBetween(const V3d& a, const V3d& b) { return std::acos(std::clamp(a.dot(b), -1.0, 1.0)); }

}  // namespace

SkyDistribution::SkyDistribution(const Sky& sky, const V3d& towardSun, int dayOfYear)
    : model_(sky.model), towardSun_(towardSun) {
    if (model_ == SkyModelType::Perez) {
        const PerezInputs in{sky.directNormalIrradiance, sky.diffuseHorizontalIrradiance, sky.dewPointC.value_or(11.0),
                             dayOfYear, towardSun};
        perez_.emplace(in, 0);
        const double zenith = perez_->relativeLuminance(V3d(0, 1, 0));
        normalisation_ = zenith > 0 ? 1.0 / zenith : 1.0;
        return;
    }
    if (model_ != SkyModelType::CieGeneral) return;
    cie_ = cieSkyParameters(sky.cieType);
    const double zs = std::min(std::acos(std::clamp(towardSun.y, -1.0, 1.0)), kPiD / 2);
    normalisation_ = 1.0 / (indicatrix(cie_, zs) * gradation(cie_, 1.0));
}

double SkyDistribution::operator()(const V3d& w) const {
    if (!(w.y > 0)) return 0.0;
    switch (model_) {
    case SkyModelType::Uniform: return 1.0;
    case SkyModelType::CieOvercast: return (1.0 + 2.0 * w.y) / 3.0;
    case SkyModelType::CieGeneral:
        return indicatrix(cie_, angleBetween(w, towardSun_)) * gradation(cie_, w.y) * normalisation_;
    case SkyModelType::Perez: return perez_->relativeLuminance(w) * normalisation_;
    }
    return 0.0;
}

double relativeSkyLuminance(const Sky& sky, const V3d& w, const V3d& towardSun) {
    return SkyDistribution(sky, towardSun)(w);
}

double relativeHorizontalIlluminance(const Sky& sky, const V3d& towardSun, int resolution) {
    if (sky.model == SkyModelType::Uniform) return kPiD;
    if (sky.model == SkyModelType::CieOvercast) return 7.0 * kPiD / 9.0;
    return relativeHorizontalIlluminance(SkyDistribution(sky, towardSun), resolution);
}

double relativeHorizontalIlluminance(const SkyDistribution& relative, int resolution) {
    return horizontalIntegral(relative, resolution);
}

double zenithLuminance(const Sky& sky, const V3d& towardSun) {
    if (sky.zenithLuminance) return *sky.zenithLuminance;
    const double eh = sky.horizontalIlluminance.value_or(0.0);
    return eh > 0 ? eh / relativeHorizontalIlluminance(sky, towardSun) : 0.0;
}

}  // namespace lucerna
