#include "core/daylight/daylight_availability.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {

constexpr double kPiD = std::numbers::pi;
constexpr double kCivilTwilightDeg = -6.0;  // the sky is dark below the sun's civil twilight

struct SkyCoefficients {
    double aKlx, bKlx, c;
};

SkyCoefficients skyCoefficients(SkyCondition condition) {
    switch (condition) {
    case SkyCondition::Clear: return {0.8, 15.5, 0.5};
    case SkyCondition::PartlyCloudy: return {0.3, 45.0, 1.0};
    case SkyCondition::Overcast: return {0.3, 21.0, 1.0};
    }
    return {0, 0, 1};
}

}  // namespace

SkyCondition skyCondition(const Sky& sky) {
    switch (sky.model) {
    case SkyModelType::CieGeneral:
        return sky.cieType <= 5 ? SkyCondition::Overcast : sky.cieType <= 10 ? SkyCondition::PartlyCloudy : SkyCondition::Clear;
    case SkyModelType::Uniform:
    case SkyModelType::CieOvercast:
    case SkyModelType::Perez: return SkyCondition::Overcast;
    }
    return SkyCondition::Overcast;
}

double relativeOpticalAirMass(double altitudeDeg) {
    const double h = std::max(altitudeDeg, 0.0);
    return 1.0 / (std::sin(h * kPiD / 180.0) + 0.50572 * std::pow(h + 6.07995, -1.6364));
}

double extraterrestrialIlluminance(std::optional<int> dayOfYear) {
    constexpr double kSolarIlluminanceConstantLux = 127500.0;
    if (!dayOfYear) return kSolarIlluminanceConstantLux;
    // The earth is nearest the sun about 2 January.
    return kSolarIlluminanceConstantLux * (1.0 + 0.034 * std::cos(2.0 * kPiD * (*dayOfYear - 2) / 365.0));
}

double skyHorizontalIlluminance(SkyCondition condition, double altitudeDeg) {
    const SkyCoefficients k = skyCoefficients(condition);
    if (altitudeDeg <= kCivilTwilightDeg) return 0.0;
    if (altitudeDeg <= 0) return 1000.0 * k.aKlx * (altitudeDeg - kCivilTwilightDeg) / -kCivilTwilightDeg;
    const double s = std::sin(std::min(altitudeDeg, 90.0) * kPiD / 180.0);
    return 1000.0 * (k.aKlx + k.bKlx * std::pow(s, k.c));
}

double sunDirectNormalIlluminance(SkyCondition condition, double altitudeDeg, std::optional<int> dayOfYear) {
    if (condition == SkyCondition::Overcast || !(altitudeDeg > 0)) return 0.0;
    const double extinction = condition == SkyCondition::Clear ? 0.21 : 0.80;
    return extraterrestrialIlluminance(dayOfYear) * std::exp(-extinction * relativeOpticalAirMass(altitudeDeg));
}

}  // namespace lucerna
