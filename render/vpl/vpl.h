#pragma once
// Virtual point lights (Keller 1997), shared by the instant radiosity and Metropolis instant
// radiosity backends and by the interactive preview.
//
// A VPL at x stands for light that arrived at x from direction `incident` with flux `power`. It
// lights a point y (scene units, no meters_per_unit: see EmissionSample) as a point light of
// intensity power * f_x(incident, x->y) * cos_x, where f_x is the BSDF of x's material:
//   L(y -> wo) = f_y(wo, y->x) * power * f_x(incident, x->y) * |cos_x| |cos_y| / |x - y|^2 * V(x, y).
// vpl_contribution.h evaluates exactly this (with an optional clamp of the geometric term).
//
// VPLs sit only on non-delta, non-emitting surfaces (diffuse, glossy): never on lights, mirrors or
// glass. The light a VPL set represents at a gathering point is therefore the INDIRECT light
// (one bounce or more); direct light is the caller's business (next-event estimation in the CPU
// backends, the preview's own direct pass).

#include "core/math.h"

#include <cstdint>
#include <vector>

namespace lucerna {

struct Vpl {
    V3f position;
    V3f normal;            // unit geometric normal, turned to the side the light arrived on
    V3f incident;          // unit, from x back toward where the light came from
    Rgb power;             // W in scene units (see EmissionSample), per VPL of the set
    uint32_t material = 0; // render-scene material id of the surface at x
    uint32_t triangle = 0;
    int bounce = 1;        // surface interactions of the light path up to x, x included:
                           // 1: lit directly by a light; 2: after one more bounce; ...
    V3f pError{0, 0, 0};   // floating-point error bound of position, for robust shadow-ray offsets
};

using VplSet = std::vector<Vpl>;

}  // namespace lucerna
