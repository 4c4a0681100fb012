#pragma once
// Daylight particles through the windows: the lines along which sky and sun particles travel,
// chosen through the glazing panes (portals) instead of anywhere across the scene, so that in a
// closed room almost none land on the roof and the facade.
//
// A particle from the environment is a direction w toward the sky and a line along -w (the
// disc of light_emission.h: a uniform point of the disc of the scene's radius facing w). With
// portals the line is drawn from a mixture: with probability kDiscShare from that disc (light
// reflected off the outside of the building, skies seen past the panes), else through a uniform
// point of the portals' area projected along w, counting only the panes whose outside faces w.
// Per unit area across the line (the plane normal to w), that density is
//   p(line | w) = kDiscShare / (pi R^2) + (1 - kDiscShare) n(line, w) / S(w),
// n the number of facing panes the line crosses, S(w) = sum_k A_k |cos theta_k| over the facing
// panes (their projected area); where no pane faces w, the disc alone: 1 / (pi R^2). Every line
// through the scene keeps a density above zero, so the estimate stays unbiased; a function of
// the line and w alone, so that bidirectional weights can evaluate it at any vertex.

#include "render/trace/lights/environment_sampler.h"

#include <string>
#include <vector>

namespace lucerna {

// The share of daylight particles that still leave from the disc around the scene.
inline constexpr float kDiscShare = 0.25f;

class DaylightPortals {
public:
    DaylightPortals() = default;
    // The portals (each with its outside side where known: Portal::outside), the scene's
    // bounding sphere. Empty without portals or past kMaxPortalTriangles.
    DaylightPortals(const std::vector<Portal>& portals, const V3f& sceneCenter, float sceneRadius);

    bool empty() const { return portals_.empty(); }

    // A point of the line a particle toward w (unit, toward the sky) travels back along, for u
    // in [0, 1)^2, and the line's density per unit area across it (above).
    V3f sampleLine(const V3f& w, const V2f& u, float& density) const;
    // p(line | w) of the line through `point` along w.
    float lineDensity(const V3f& point, const V3f& w) const;

    const std::vector<Portal>& portals() const { return portals_; }
    // Whether a particle toward w (unit, toward the sky) can come in through a portal: some
    // portal's outside faces w; otherwise sampleLine() draws it from the disc.
    bool letsIn(const V3f& w) const { return projectedArea(w) > 0; }
    // One line for `lucerna info`: "4 portal triangles (panes and openings), 3.20 m^2, outside
    // known for 4 (daylight particles: 75% through them)", or "none (...)".
    std::string describe(float metersPerUnit) const;

private:
    // Whether pane k lets particles in toward -w: its outside faces w (either side where unknown).
    bool facing(size_t k, const V3f& w) const;
    float projectedArea(const V3f& w) const;
    // lineDensity with the facing portals' projected area s = projectedArea(w) known.
    float lineDensity(const V3f& point, const V3f& w, float s) const;

    std::vector<Portal> portals_;
    V3f center_{0, 0, 0};
    float radius_ = 1;
};

}  // namespace lucerna
