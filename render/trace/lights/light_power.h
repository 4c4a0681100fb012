#pragma once
// Choosing a light in proportion to its power: the selection that particles leaving the lights
// always use, next-event estimation with LightSelection::Power, and the one density of a light
// path's origin that BDPT's MIS weights use. Lights are numbered as LightSample::light: the
// emissive triangles, then the delta lights, then the environment.

#include "render/trace/discrete_distribution.h"

#include <cstdint>
#include <vector>

namespace lucerna {

struct DeltaLight;
struct EmitterTriangle;
class EnvironmentLight;

class PowerSelection {
public:
    PowerSelection() = default;
    // Every light's power in one unit (irradiance times scene units squared; luminance weights
    // the channels): a directional light's and the environment's over the scene's cross-section
    // of radius sceneRadius. triangleCount sizes the per-triangle table of areaPdf().
    PowerSelection(const std::vector<EmitterTriangle>& emitters, const std::vector<DeltaLight>& deltas,
                   const EnvironmentLight* environment, float metersPerUnit, float sceneRadius, size_t triangleCount);

    // No light gives any power.
    bool empty() const { return select_.empty(); }
    size_t size() const { return select_.size(); }
    // A light for u in [0, 1), never one of zero power; the only light without drawing.
    size_t sample(float u) const { return select_.size() > 1 ? select_.sample(u) : 0; }
    // The probability that sample() chooses `light`.
    float pdf(size_t light) const { return select_.size() > 1 ? float(select_.pdf(light)) : 1.0f; }
    // The sum of the powers.
    double total() const { return select_.total(); }
    // The density of choosing render-scene triangle `triangle` and a uniform point on it, per
    // unit area; 0 for a triangle that does not emit.
    float areaPdf(uint32_t triangle) const { return triangle < areaPdf_.size() ? areaPdf_[triangle] : 0.0f; }

private:
    DiscreteDistribution select_;
    std::vector<float> areaPdf_;  // by render-scene triangle: selection pdf / area
};

}  // namespace lucerna
