#pragma once
// Daylight particles through the windows: the directions and lines along which sky and sun
// particles travel, chosen through the glazing panes and openings (portals) instead of anywhere
// across the scene, so that in a closed room almost none land on the roof and the facade.
//
// A particle from the environment is a direction w toward the sky and a line along -w. Without
// portals: w from the environment's own table, the line through a uniform point of the disc of
// the scene's radius facing w (light_emission.h). With portals, a mixture of two ways:
//   - with probability kDiscShare, that same way (light reflected off the outside of the
//     building, skies seen past the panes, directions no portal faces);
//   - otherwise w in proportion to the radiance times S(w), the portals' area projected along w
//     (only the portals whose outside faces w), and the line through a uniform point of that
//     projected area.
// The joint density of (w, line), per steradian and per unit area across the line, is
//   p(w, line) = kDiscShare p_env(w) / (pi R^2) + (1 - kDiscShare) q(w) n(line, w) / S(w),
// p_env the environment's density, q the portals' direction density (f S / integral of f S, f
// the environment's table), n the number of facing portals the line crosses. Every direction and
// line that carries light keeps a density above zero, so estimates stay unbiased; drawing w with
// S gives every portal particle the same weight, and no portal particle misses the windows.
// A directional light's particles (a sun of diameter 0) have one direction: their lines come
// from the same mixture of the disc and the portals facing it.

#include "render/trace/lights/environment_light.h"
#include "render/trace/lights/environment_sampler.h"

#include <string>
#include <vector>

namespace lucerna {

// The share of daylight particles that still leave from the disc around the scene.
inline constexpr float kDiscShare = 0.25f;

// One particle's direction and line.
struct DaylightParticle {
    V3f towardSky{0, 1, 0};  // w, unit; the particle travels along -w
    V3f point{0, 0, 0};      // a point of its line, outside the scene's sphere
    Rgb radiance{0, 0, 0};   // arriving along -w
    float pdfDirection = 0;  // p_env(w), the environment's own solid-angle density
    float lineDensity = 0;   // p(w, line) / p_env(w): DaylightPortals::lineDensity(point, towardSky)
};

class DaylightPortals {
public:
    DaylightPortals() = default;
    // The portals (each with its outside side where known: Portal::outside), the environment
    // they let in, the scene's bounding sphere. Empty without portals, past
    // kMaxPortalTriangles, or where no portal faces any direction the environment lights.
    DaylightPortals(const std::vector<Portal>& portals, const EnvironmentLight& environment, const V3f& sceneCenter,
                    float sceneRadius);

    bool empty() const { return portals_.empty(); }

    // A particle for uLine, uDirection in [0, 1)^2; false when nothing could be drawn.
    bool sample(const V2f& uLine, const V2f& uDirection, DaylightParticle& out) const;
    // p(w, line) / p_env(w) for the line through `point` along w (unit, toward the sky): per unit
    // area across the line, the density of the line given w were w drawn by the environment's
    // own density. Bidirectional weights multiply it by the direction density they use.
    float lineDensity(const V3f& point, const V3f& w) const;

    // Directional lights (a sun of diameter 0): the line along which a particle travelling along
    // -w (w unit, toward the light) leaves, and its density across it: where a portal faces w,
    // kDiscShare / (pi R^2) + (1 - kDiscShare) n(line, w) / S(w); elsewhere the disc's 1 / (pi R^2).
    V3f sampleParallel(const V3f& w, const V2f& u, float& density) const;
    float parallelDensity(const V3f& point, const V3f& w) const;

    const std::vector<Portal>& portals() const { return portals_; }
    // Whether a particle toward w (unit, toward the sky) can come in through a portal: some
    // portal's outside faces w.
    bool letsIn(const V3f& w) const { return projectedArea(w) > 0; }
    // One line for `lucerna info`: "4 portal triangles (panes and openings), 3.20 m^2, outside
    // known for 4 (daylight particles: 75% through them)", or "none (...)".
    std::string describe(float metersPerUnit) const;

private:
    // The portals of one orientation: S(w) sums over these (rooms have few).
    struct Facing {
        V3f normal;
        int8_t outside = 0;
        float area = 0;
    };
    // Whether a portal of this orientation lets particles in toward -w: its outside faces w
    // (either side where unknown).
    static bool faces(const V3f& normal, int8_t outside, const V3f& w);
    float projectedArea(const V3f& w) const;  // S(w)
    int crossings(const V3f& point, const V3f& w) const;  // n(line, w)
    // A point of the line along w through a uniform point of the facing portals' projected
    // area s = S(w) > 0, moved along the line to the disc's plane.
    V3f throughPortal(const V3f& w, float s, V2f u) const;
    V3f onDisc(const V3f& w, const V2f& u) const;

    std::vector<Portal> portals_;
    std::vector<Facing> orientations_;
    EnvironmentLight environment_;    // p_env
    EnvironmentLight throughPortals_; // q: the environment's table weighted by S
    V3f center_{0, 0, 0};
    float radius_ = 1;
};

}  // namespace lucerna
