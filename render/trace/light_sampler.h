#pragma once
// Next-event estimation: choosing a light in proportion to its power and a point or direction on
// it. Emissive triangles are one-sided (SPEC.md); point, spot and directional lights are delta
// lights that no ray can hit. A scene with a single emitter skips the selection table.

#include "core/scene.h"
#include "render/trace/discrete_distribution.h"
#include "render/trace/embree_scene.h"
#include "render/trace/surface_point.h"

#include <vector>

namespace lucerna {

struct DeltaLight {
    LightType type = LightType::Point;
    V3f position;
    V3f direction;    // unit: the spot's axis, or the direction a directional light travels
    Rgb intensity;    // point, spot: W/sr (on axis); directional: irradiance, W/m^2
    float cosCone = -1.0f, cosFalloffStart = -1.0f;  // spot only

    // Spot: SPEC.md's smoothstep(cos(cone), cos(falloff_start), cos theta), 1 inside a hard cone.
    float spotFactor(float cosTheta) const;
};

struct EmitterTriangle {
    uint32_t triangle = 0;   // index into the render scene's triangles
    V3f p0, p1, p2;
    V3f normal;              // unit, front side
    float area = 0;          // scene units^2
    Rgb radiance;            // W sr^-1 m^-2, front side only
};

struct LightSample {
    V3f wi;          // unit, from the shading point toward the light
    Rgb value;       // radiance arriving along wi (area), or the delta light's irradiance at normal incidence
    float pdf = 0;   // solid angle pdf (area lights), or the selection probability (delta lights)
    bool isDelta = false;
    Ray shadowRay;   // offset at both ends; occluded() on it decides visibility
};

class LightSampler {
public:
    LightSampler() = default;
    // sceneRadius bounds the geometry (a directional light's power is its irradiance over the
    // scene's cross-section); triangleCount sizes the per-triangle pdf table for MIS.
    LightSampler(std::vector<EmitterTriangle> emitters, std::vector<DeltaLight> deltas, float metersPerUnit,
                 float sceneRadius, size_t triangleCount);

    bool empty() const { return emitters_.empty() && deltas_.empty(); }
    const std::vector<EmitterTriangle>& emitters() const { return emitters_; }
    const std::vector<DeltaLight>& deltaLights() const { return deltas_; }

    // A light sample for the shading point `ref`; false when the chosen light cannot reach it
    // (back of an emitter, outside a spot's cone, zero power).
    bool sample(const SurfacePoint& ref, const V2f& u, float uSelect, LightSample& out) const;

    // Solid-angle pdf with which sample() yields the point q (unit normal nq) of emissive
    // triangle `triangle`, seen from p. 0 for a triangle that does not emit.
    float pdfEmitter(uint32_t triangle, const V3f& p, const V3f& q, const V3f& nq) const;

private:
    bool sampleEmitter(const EmitterTriangle& e, float selectPdf, const SurfacePoint& ref, const V2f& u,
                       LightSample& out) const;
    bool sampleDelta(const DeltaLight& l, float selectPdf, const SurfacePoint& ref, LightSample& out) const;

    std::vector<EmitterTriangle> emitters_;
    std::vector<DeltaLight> deltas_;
    DiscreteDistribution select_;       // over emitters_ then deltas_; unused with one entry
    std::vector<float> areaPdf_;        // by render-scene triangle: selection pdf / area (0: not an emitter)
    float metersPerUnit_ = 1.0f;
};

}  // namespace lucerna
