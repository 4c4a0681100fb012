#pragma once
// Next-event estimation: choosing a light for a shading point, by a light tree (the default) or
// in proportion to power, and a point or direction on it; and particles leaving the lights, chosen
// by power. Emissive triangles are one-sided (SPEC.md); point, spot, luminaire and directional
// lights are delta lights that no ray can hit; daylight (sky, ground, the sun's disc) is one
// environment light at infinity that rays leaving the scene see. A scene with a single emitter
// skips the selection table.

#include "render/trace/embree_scene.h"
#include "render/trace/lights/delta_light.h"
#include "render/trace/lights/emitter_triangle.h"
#include "render/trace/lights/environment_sampler.h"
#include "render/trace/lights/light_emission.h"
#include "render/trace/lights/light_power.h"
#include "render/trace/lights/tree_selection.h"
#include "render/trace/surface_point.h"

#include <optional>
#include <vector>

namespace lucerna {

struct LightSample {
    V3f wi;          // unit, from the shading point toward the light
    Rgb value;       // radiance arriving along wi (area), or the delta light's irradiance at normal incidence
    float pdf = 0;   // solid angle pdf (area lights), or the selection probability (delta lights)
    bool isDelta = false;
    Ray shadowRay;   // offset at both ends; occluded() on it decides visibility
    // Which light: emitters()[light], deltaLights()[light - emitters().size()], or the
    // environment (environmentIndex()); and the point sampled on it (area, point, spot; unused
    // for directional and the environment). Bidirectional MIS needs both.
    uint32_t light = 0;
    V3f position{0, 0, 0};
};

// How next-event estimation chooses a light: in proportion to power everywhere, or by a light
// tree by each light's importance at the shading point (`--option light_sampler=power|tree`).
enum class LightSelection { Power, Tree };
// The choice where none is asked for: the tree (BENCHMARKS.md, "Many lights (issue 19)").
constexpr LightSelection kDefaultLightSelection = LightSelection::Tree;

class LightSampler {
public:
    LightSampler() = default;
    // sceneRadius bounds the geometry (a directional light's power is its irradiance over the
    // scene's cross-section); triangleCount sizes the per-triangle pdf table for MIS.
    LightSampler(std::vector<EmitterTriangle> emitters, std::vector<DeltaLight> deltas, float metersPerUnit,
                 const V3f& sceneCenter, float sceneRadius, size_t triangleCount,
                 LightSelection selection = kDefaultLightSelection,
                 std::optional<EnvironmentLight> environment = std::nullopt, std::vector<Portal> portals = {},
                 bool particlePortals = true);

    bool empty() const { return emitters_.empty() && deltas_.empty() && !environment_; }
    const std::vector<EmitterTriangle>& emitters() const { return emitters_; }
    const std::vector<DeltaLight>& deltaLights() const { return deltas_; }
    const EnvironmentLight* environment() const { return environment_ ? &environment_->light() : nullptr; }
    // The environment's number in LightSample::light's numbering (after every other light).
    uint32_t environmentIndex() const { return uint32_t(emitters_.size() + deltas_.size()); }
    bool isEnvironment(uint32_t light) const { return environment_ && light == environmentIndex(); }
    // A point far up the unit direction dir from p, outside the scene: where bidirectional
    // methods place a vertex of a light at infinity (directional, environment).
    V3f farAlong(const V3f& p, const V3f& dir) const {
        return p + dir * (2.0f * sceneRadius_ + (p - sceneCenter_).length());
    }

    // A light sample for the shading point `ref`; false when the chosen light cannot reach it
    // (back of an emitter, outside a spot's cone, zero power). With the tree, directional lights
    // are chosen beside it, each as often as the whole tree.
    // `receiving`: the unit normal of the side of ref that takes light (an opaque surface's side
    // facing the viewer), which lets the tree skip lights behind it; zero for any side. The power
    // selection ignores it.
    bool sample(const SurfacePoint& ref, const V2f& u, float uSelect, LightSample& out,
                const V3f& receiving = V3f(0, 0, 0)) const;
    // The sample of delta light deltaLights()[index] for `ref`, as sample() gives it but with
    // selection probability 1: estimators that sum every delta light exactly (calculation grids)
    // instead of choosing one. False when the light cannot reach ref.
    bool sampleDeltaLight(size_t index, const SurfacePoint& ref, LightSample& out) const;

    // Chooses a light in proportion to power and a particle leaving it (light_emission.h). False
    // for a scene without lights.
    bool sampleEmission(const V2f& uPosition, const V2f& uDirection, float uSelect, EmissionSample& out) const;
    // The density across the line (per unit area of the plane normal to it, scene units) with
    // which sampleEmission() sends an environment particle along the line through `point`
    // toward -towardSky (unit), the environment once chosen and the direction drawn by its own
    // density: the disc's 1 / (pi R^2), or the mixture through the windows over that density
    // (DaylightPortals::lineDensity).
    float environmentLineDensity(const V3f& point, const V3f& towardSky) const;
    // The same for a directional light's particles along -towardLight (unit): the disc's, or
    // DaylightPortals::parallelDensity.
    float directionalLineDensity(const V3f& point, const V3f& towardLight) const;
    // The windows daylight particles are sent through (empty: none, or no environment).
    const DaylightPortals& particlePortals() const { return particlePortals_; }
    // Total emitted power in the scene's units (selection weights' sum): the normalisation of
    // light tracing.
    double totalPower() const { return power_.total(); }

    // Solid-angle pdf with which sample() yields the point q (unit normal nq) of emissive
    // triangle `triangle`, seen from p (sample()'s ref.p, with its `receiving`). 0 for a
    // triangle that does not emit.
    float pdfEmitter(uint32_t triangle, const V3f& p, const V3f& q, const V3f& nq,
                     const V3f& receiving = V3f(0, 0, 0)) const;
    // The area density with which sample() and sampleEmission() would choose a point of the
    // emissive triangle were the light chosen by power: the one density BDPT's MIS weights use
    // for a light-path origin, whatever chose the light (they only need to agree across
    // strategies, pbrt-v4's PdfLightOrigin does the same).
    float areaPdfByPower(uint32_t triangle) const { return power_.areaPdf(triangle); }

    // How much likelier sample() at p (with its `receiving`) chooses light `light` (LightSample::
    // light numbering) than sampleEmission() does by power: the tree's probability over power's,
    // 1 under power selection, 0 where the tree never chooses it there. Bidirectional methods
    // weigh next-event estimation (s = 1) against the strategies whose light subpath starts by
    // power with it (bdpt_tracer.h).
    float selectionRatio(uint32_t light, const V3f& p, const V3f& receiving) const;
    // The same for the emitter of render-scene triangle `triangle` (0 for one that does not emit).
    float emitterSelectionRatio(uint32_t triangle, const V3f& p, const V3f& receiving) const;

    // Solid-angle pdf with which sample() yields the environment's direction w (unit, out of the
    // scene) at p (sample()'s ref.p; the portals make it depend on p). 0 without an environment.
    float pdfEnvironment(const V3f& w, const V3f& p) const;
    // The same were the light chosen by power (BDPT's light-path origin, as areaPdfByPower).
    float pdfEnvironmentByPower(const V3f& w, const V3f& p) const;

private:
    bool sampleEmitter(const EmitterTriangle& e, float selectPdf, const SurfacePoint& ref, const V2f& u,
                       LightSample& out) const;
    bool sampleDelta(const DeltaLight& l, float selectPdf, const SurfacePoint& ref, LightSample& out) const;
    bool sampleEnvironment(float selectPdf, const SurfacePoint& ref, const V2f& u, LightSample& out) const;
    // The probability that sample() chooses the environment (the same wherever it is).
    float environmentSelectPdf() const;

    std::vector<EmitterTriangle> emitters_;
    std::vector<DeltaLight> deltas_;
    std::optional<EnvironmentSampler> environment_;
    DaylightPortals particlePortals_;
    PowerSelection power_;
    TreeSelection tree_;  // empty with power selection
    float metersPerUnit_ = 1.0f;
    V3f sceneCenter_{0, 0, 0};
    float sceneRadius_ = 1.0f;
};

}  // namespace lucerna
