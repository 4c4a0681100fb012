#include "core/daylight/sun_path_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {
constexpr double kPiD = std::numbers::pi;
constexpr double kDeg = kPiD / 180.0;
// The declination never leaves +-23.45 degrees; the grid covers it with a margin.
constexpr double kMaxDeclination = 23.5 * kDeg;
}  // namespace

SunPathGrid::SunPathGrid(double latitudeDeg, const V3d& north, double declinationStepDeg, double hourAngleStepDeg)
    : latitude_(latitudeDeg * kDeg), north_(north.normalized()) {
    east_ = north_.cross(V3d(0, 1, 0)).normalized();
    declinations_ = std::max(2, int(std::ceil(2 * kMaxDeclination / (declinationStepDeg * kDeg))) + 1);
    declinationStep_ = 2 * kMaxDeclination / (declinations_ - 1);
    hourAngles_ = std::max(4, int(std::ceil(360.0 / hourAngleStepDeg)));
    hourAngleStep_ = 2 * kPiD / hourAngles_;
    for (int i = 0; i < declinations_; ++i)
        for (int j = 0; j < hourAngles_; ++j)
            direction_.push_back(direction(-kMaxDeclination + i * declinationStep_, -kPiD + j * hourAngleStep_));
}

void SunPathGrid::equatorial(const V3d& w, double& declination, double& hourAngle) const {
    const double e = w.dot(east_), n = w.dot(north_), u = w.y;
    const double sl = std::sin(latitude_), cl = std::cos(latitude_);
    declination = std::asin(std::clamp(u * sl + n * cl, -1.0, 1.0));
    hourAngle = std::atan2(-e, u * cl - n * sl);
}

V3d SunPathGrid::direction(double declination, double hourAngle) const {
    const double sl = std::sin(latitude_), cl = std::cos(latitude_);
    const double sd = std::sin(declination), cd = std::cos(declination), ch = std::cos(hourAngle);
    const double u = sl * sd + cl * cd * ch, n = cl * sd - sl * cd * ch, e = -cd * std::sin(hourAngle);
    return (east_ * e + north_ * n + V3d(0, u, 0)).normalized();
}

SunPathGrid::Stencil SunPathGrid::stencil(const V3d& towardSun) const {
    double declination = 0, hourAngle = 0;
    equatorial(towardSun, declination, hourAngle);
    const double x = std::clamp((declination + kMaxDeclination) / declinationStep_, 0.0, declinations_ - 1.000001);
    const double y = (hourAngle + kPiD) / hourAngleStep_;
    const int i = int(x), j = int(std::floor(y));
    const double fx = x - i, fy = y - j;
    const int j0 = ((j % hourAngles_) + hourAngles_) % hourAngles_, j1 = (j0 + 1) % hourAngles_;
    Stencil s;
    s.node[0] = i * hourAngles_ + j0, s.weight[0] = (1 - fx) * (1 - fy);
    s.node[1] = i * hourAngles_ + j1, s.weight[1] = (1 - fx) * fy;
    s.node[2] = (i + 1) * hourAngles_ + j0, s.weight[2] = fx * (1 - fy);
    s.node[3] = (i + 1) * hourAngles_ + j1, s.weight[3] = fx * fy;
    return s;
}

}  // namespace lucerna
