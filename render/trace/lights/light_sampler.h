#pragma once
// Next-event estimation: choosing a light in proportion to its power and a point or direction on
// it. Emissive triangles are one-sided (SPEC.md); point, spot and directional lights are delta
// lights that no ray can hit; daylight (sky, ground, the sun's disc) is one environment light
// at infinity that rays leaving the scene see. A scene with a single emitter skips the
// selection table.

#include "core/scene/scene.h"
#include "render/trace/discrete_distribution.h"
#include "render/trace/embree_scene.h"
#include "render/trace/lights/environment_light.h"
#include "render/trace/lights/goniometric_sampler.h"
#include "render/trace/lights/light_tree.h"
#include "render/trace/surface_point.h"

#include <map>
#include <memory>
#include <vector>

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
    // Point, spot, luminaire: the solid-angle density with which sampleEmission() leaves toward w.
    float pdfDirection(const V3f& w) const;
    // Luminaire: w in the (C0, C90, nadir) frame.
    V3f toLuminaire(const V3f& w) const { return V3f(w.dot(c0), w.dot(c90), w.dot(direction)); }
};

// Luminaire samplers by distribution, so that lights sharing a file share one (a floor of
// identical luminaires builds the table's sampling distribution once).
using GoniometricSamplers = std::map<const GoniometricDistribution*, std::shared_ptr<const GoniometricSampler>>;

// The float form of a scene light (SPEC.md units: intensity in W/sr, not yet divided by mpu^2);
// with `samplers`, a luminaire's sampler is taken from or added to it.
DeltaLight compileDeltaLight(const Light& light, GoniometricSamplers* samplers = nullptr);

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
    // Which light: emitters()[light], deltaLights()[light - emitters().size()], or the
    // environment (environmentIndex()); and the point sampled on it (area, point, spot; unused
    // for directional and the environment). Bidirectional MIS needs both.
    uint32_t light = 0;
    V3f position{0, 0, 0};
};

// A light particle leaving a light, for light tracing, bidirectional methods and VPLs.
//
// Units: every backend works in scene units. A delta light's intensity is divided by
// meters_per_unit^2 at emission (SPEC.md's E = I cos / (d mpu)^2 with d in scene units), so that
// the flux of any particle, from any light, is in W per scene-unit^2 of the scene's area measure
// and the geometric term cos cos / d^2 stays in scene units everywhere.
struct EmissionSample {
    V3f position;
    V3f normal;          // the emitter's front normal; the direction itself for delta lights
    V3f direction;       // unit, leaving the light
    Rgb power;           // Le cos / (pdfPosition pdfDirection) or its delta-light equivalent
    float pdfPosition = 0;   // area measure, light selection included (1 per selection for delta positions)
    float pdfDirection = 0;  // solid angle (0 for the directional light's delta direction)
    bool deltaPosition = false, deltaDirection = false;
    uint32_t triangle = 0xffffffffu;  // the emissive triangle, if any
    SurfacePoint surface() const;     // the point on an area light, for spawning the first ray
    V3f pError{0, 0, 0};              // error bound of position (area lights)
    uint32_t light = 0;               // which light, numbered as LightSample::light
    bool environment = false;         // from the environment: position is on a disc outside the scene
};

// A glazing triangle through which daylight enters (Bitterli et al. 2015, "Portal-masked
// environment map sampling"): next-event estimation of the environment also aims at points on
// the panes, so that a room lit through its windows does not spend most sky samples on its walls.
struct Portal {
    V3f p0, p1, p2;
    V3f normal;      // unit
    float area = 0;  // scene units^2
};
// Past this many pane triangles the portals are not used (each density evaluation loops over them).
inline constexpr size_t kMaxPortalTriangles = 512;

// How next-event estimation chooses a light: in proportion to power everywhere, or by a light
// tree by each light's importance at the shading point (`--option light_sampler=power|tree`).
enum class LightSelection { Power, Tree };
// The choice where none is asked for: the tree (BENCHMARKS.md, "Many lights").
constexpr LightSelection kDefaultLightSelection = LightSelection::Tree;

class LightSampler {
public:
    LightSampler() = default;
    // sceneRadius bounds the geometry (a directional light's power is its irradiance over the
    // scene's cross-section); triangleCount sizes the per-triangle pdf table for MIS.
    LightSampler(std::vector<EmitterTriangle> emitters, std::vector<DeltaLight> deltas, float metersPerUnit,
                 const V3f& sceneCenter, float sceneRadius, size_t triangleCount,
                 LightSelection selection = kDefaultLightSelection,
                 std::optional<EnvironmentLight> environment = std::nullopt, std::vector<Portal> portals = {});

    bool empty() const { return emitters_.empty() && deltas_.empty() && !environment_; }
    const std::vector<EmitterTriangle>& emitters() const { return emitters_; }
    const std::vector<DeltaLight>& deltaLights() const { return deltas_; }
    const EnvironmentLight* environment() const { return environment_ ? &*environment_ : nullptr; }
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

    // Chooses a light in proportion to power and a particle leaving it: area lights by uniform
    // position and cosine direction, point lights uniformly over the sphere, spots uniformly over
    // their cone, luminaires by their distribution (GoniometricSampler), directional lights over a disk of the scene's radius facing them. False for a
    // scene without lights.
    bool sampleEmission(const V2f& uPosition, const V2f& uDirection, float uSelect, EmissionSample& out) const;
    // Total emitted power in the scene's units (selection weights' sum): the normalisation of
    // light tracing.
    double totalPower() const { return select_.total(); }

    // Solid-angle pdf with which sample() yields the point q (unit normal nq) of emissive
    // triangle `triangle`, seen from p (sample()'s ref.p, with its `receiving`). 0 for a
    // triangle that does not emit.
    float pdfEmitter(uint32_t triangle, const V3f& p, const V3f& q, const V3f& nq,
                     const V3f& receiving = V3f(0, 0, 0)) const;
    // The area density with which sample() and sampleEmission() would choose a point of the
    // emissive triangle were the light chosen by power: the one density BDPT's MIS weights use
    // for a light-path origin, whatever chose the light (they only need to agree across
    // strategies, pbrt-v4's PdfLightOrigin does the same).
    float areaPdfByPower(uint32_t triangle) const { return triangle < areaPdf_.size() ? areaPdf_[triangle] : 0.0f; }

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
    bool emitFromEnvironment(float selectPdf, const V2f& uPosition, const V2f& uDirection, EmissionSample& out) const;
    // The probability that sample() chooses the environment (the same wherever it is).
    float environmentSelectPdf() const;
    // The environment's direction density at p: its own sampling mixed with the portals'.
    float environmentDirectionPdf(const V3f& w, const V3f& p) const;
    // Solid-angle density of aiming at a uniform point of the panes (by area) from p toward w.
    float portalPdf(const V3f& w, const V3f& p) const;
    float portalShare() const { return portals_.empty() ? 0.0f : 0.5f; }
    void buildTree(size_t triangleCount);
    // Tree selection: the light (emitters_ then deltas_ numbering) and its probability at p.
    bool selectByTree(const V3f& p, const V3f& n, float u, size_t& index, float& pdf) const;

    std::vector<EmitterTriangle> emitters_;
    std::vector<DeltaLight> deltas_;
    std::optional<EnvironmentLight> environment_;
    std::vector<Portal> portals_;
    DiscreteDistribution portalSelect_;  // by area
    float portalArea_ = 0;
    DiscreteDistribution select_;       // over emitters_, deltas_, then the environment; unused with one entry
    std::vector<float> areaPdf_;        // by render-scene triangle: selection pdf / area (0: not an emitter)
    // Tree selection only: the tree, whose light k is leaves_[k]: a cluster of emissive
    // triangles or one point, spot or luminaire light; the directional lights and the
    // environment beside it (directional_); each emitter's share of its cluster (by area); each emissive triangle's leaf (-1: none).
    struct TreeLeaf {
        uint32_t begin = 0, end = 0;  // lights [begin, end) in emitters_ then deltas_ numbering
        float area = 0;               // a cluster's area, scene units^2
    };
    LightTree tree_;
    std::vector<TreeLeaf> leaves_;
    std::vector<uint32_t> directional_;
    std::vector<float> shareInLeaf_;
    std::vector<int32_t> leafOfTriangle_;
    float metersPerUnit_ = 1.0f;
    V3f sceneCenter_{0, 0, 0};
    float sceneRadius_ = 1.0f;
};

}  // namespace lucerna
