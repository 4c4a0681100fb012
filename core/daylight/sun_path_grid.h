#pragma once
// The positions the sun can take at a site, as a grid in declination and hour angle: every hour
// of a year falls in one of its cells, so that a quantity that varies smoothly with the sun's
// direction (the light the sun gives a point after reflections) is computed at the nodes once
// and interpolated bilinearly for each hour, instead of once per hour.

#include "core/math.h"

#include <vector>

namespace lucerna {

class SunPathGrid {
public:
    // north: the site's horizontal north (east = north x up); steps in degrees.
    SunPathGrid(double latitudeDeg, const V3d& north, double declinationStepDeg, double hourAngleStepDeg);

    int nodeCount() const { return int(direction_.size()); }
    // Unit direction toward the sun at node i (up is +y); below the horizon for some.
    const V3d& nodeDirection(int i) const { return direction_[size_t(i)]; }

    // The four nodes around a direction toward the sun and their bilinear weights (summing to 1).
    struct Stencil {
        int node[4];
        double weight[4];
    };
    Stencil stencil(const V3d& towardSun) const;

    // Declination and hour angle (radians; the hour angle positive in the afternoon) of a
    // direction toward the sun, and back.
    void equatorial(const V3d& towardSun, double& declination, double& hourAngle) const;
    V3d direction(double declination, double hourAngle) const;

private:
    double latitude_, declinationStep_, hourAngleStep_;
    V3d north_, east_;
    int declinations_ = 0, hourAngles_ = 0;
    std::vector<V3d> direction_;  // row-major: declination index * hourAngles_ + hour-angle index
};

}  // namespace lucerna
