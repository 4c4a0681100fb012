#pragma once
// Point, spot, luminaire and directional lights: delta lights, which no ray can hit, in the float
// form the tracers use (SPEC.md units: intensity in W/sr, not yet divided by meters_per_unit^2).

#include "core/scene/scene.h"
#include "render/trace/lights/goniometric_sampler.h"

#include <map>
#include <memory>

namespace lucerna {

struct DeltaLight {
    LightType type = LightType::Point;
    V3f position;
    V3f direction;    // unit: the spot's axis, the luminaire's nadir, or the direction a directional light travels
    Rgb intensity;    // point, spot: W/sr (on axis); luminaire: W/sr per candela of its table; directional: irradiance, W/m^2
    float cosCone = -1.0f, cosFalloffStart = -1.0f;  // spot only
    V3f c0{1, 0, 0}, c90{0, 0, 1};                   // luminaire: its C0 and C90 directions (core/photometry/luminaire.h)
    std::shared_ptr<const GoniometricSampler> goniometric;  // luminaire: its distribution

    // Spot: SPEC.md's smoothstep(cos(cone), cos(falloff_start), cos theta), 1 inside a hard cone.
    float spotFactor(float cosTheta) const;
    // Point, spot, luminaire: the intensity toward unit world direction w (leaving the light) is
    // intensity * factor(w); for a luminaire the factor is the table's candela.
    float factor(const V3f& w) const;
    // Point, spot, luminaire: the solid-angle density with which a particle leaves toward w
    // (emitFromDeltaLight, light_emission.h).
    float pdfDirection(const V3f& w) const;
    // Luminaire: w in the (C0, C90, nadir) frame.
    V3f toLuminaire(const V3f& w) const { return V3f(w.dot(c0), w.dot(c90), w.dot(direction)); }
};

// Luminaire samplers by distribution, so that lights sharing a file share one (a floor of
// identical luminaires builds the table's sampling distribution once).
using GoniometricSamplers = std::map<const GoniometricDistribution*, std::shared_ptr<const GoniometricSampler>>;

// The float form of a scene light; with `samplers`, a luminaire's sampler is taken from or added
// to it. A sun gives a black directional light (RenderScene places daylight itself).
DeltaLight compileDeltaLight(const Light& light, GoniometricSamplers* samplers = nullptr);

}  // namespace lucerna
