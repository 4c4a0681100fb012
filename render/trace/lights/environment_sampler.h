#pragma once
// Next-event estimation of the environment (daylight at infinity) through the glazing: half the
// directions from the environment's own sampling, half aimed at a uniform point of the window
// panes, the portals (Bitterli et al. 2015, "Portal-masked environment map sampling"), so that a
// room lit through its windows does not spend most sky samples on its walls.

#include "render/trace/discrete_distribution.h"
#include "render/trace/lights/environment_light.h"

#include <vector>

namespace lucerna {

// A glazing triangle through which daylight enters.
struct Portal {
    V3f p0, p1, p2;
    V3f normal;      // unit
    float area = 0;  // scene units^2
    // Which side is outside (RenderScene traces it): +1 the normal's, -1 the other, 0 not known
    // (either: a pane open on both sides, or closed on both).
    int8_t outside = 0;
};
// Past this many pane triangles the portals are not used (each density evaluation loops over them).
inline constexpr size_t kMaxPortalTriangles = 512;

class EnvironmentSampler {
public:
    // The portals serve a sky only (aimed at a pane, a sample finds the sun's tiny disc almost
    // never); they are left out without one, past kMaxPortalTriangles, or of no area.
    EnvironmentSampler(EnvironmentLight environment, std::vector<Portal> portals);

    const EnvironmentLight& light() const { return environment_; }
    // A direction wi (unit, out of the scene) from p, for u in [0, 1)^2, and the radiance
    // arriving along it; false where none could be drawn or it is black.
    bool sample(const V3f& p, const V2f& u, V3f& wi, Rgb& radiance) const;
    // The solid-angle density with which sample() at p yields w.
    float pdf(const V3f& w, const V3f& p) const;

private:
    // The density of aiming at a uniform point of the panes (by area) from p toward w.
    float portalPdf(const V3f& w, const V3f& p) const;
    float portalShare() const { return portals_.empty() ? 0.0f : 0.5f; }

    EnvironmentLight environment_;
    std::vector<Portal> portals_;
    DiscreteDistribution portalSelect_;  // by area
    float portalArea_ = 0;
};

}  // namespace lucerna
