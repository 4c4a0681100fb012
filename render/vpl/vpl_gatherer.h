#pragma once
// The camera side of instant radiosity, shared by `ir` and `mir`: the radiance along a camera ray
// as
//   L = (emitters seen directly or through mirrors and glass)
//     + direct light at the first diffuse/glossy vertex x1 (next-event estimation and a BSDF
//       sample, combined by the power heuristic, as the path backend does; the mean of
//       GatherSettings::directSamples such pairs)
//     + indirect light at x1 from the VPLs, geometric term clamped to maxG
//     + the clamped-away residual (Kollig & Keller 2004): the first pair's BSDF sample, when it
//       hits a diffuse/glossy x2, weighted by max(0, 1 - maxG / G(x1, x2)) times the light
//       leaving x2 toward x1, estimated by path tracing from x2, by these same terms at x2, or
//       by both (GatherSettings::residualVplShare); when it hits a mirror or glass, continued
//       by path tracing unweighted (VPL connections are straight segments, so light reaching x1
//       through a specular surface is not in the VPL term).
// Since  int f L G V dA = int f L min(G, b) V dA + int f L G max(0, 1 - b/G) V dA,  the sum is
// consistent whatever the clamp: the VPLs estimate the first integral, the paths the second.

#include "render/trace/path_tracer.h"
#include "render/trace/rng.h"
#include "render/vpl/gather_settings.h"
#include "render/vpl/instant_radiosity.h"
#include "render/vpl/vpl_contribution.h"

#include <span>

namespace lucerna {

// The first non-specular vertex of a camera path (through mirrors and glass).
struct CameraVertex {
    bool found = false;
    VplReceiver receiver;         // x1, its material, the direction back along the path
    Rgb throughput{1, 1, 1};      // of the specular chain before x1
    Rgb emitted{0, 0, 0};         // emitters seen directly or through the specular chain
};

// Follows `ray` through delta surfaces (drawing 3 numbers from u at each, none elsewhere) to the
// first diffuse/glossy vertex. With sensorPoint >= 0 the ray is that point's of the scene's
// camera, and what it finds before scattering is weighed by sensorRayWeight (sensor_direct.h).
CameraVertex traceCameraVertex(const RenderScene& scene, Ray ray, SampleGenerator& u, int maxSpecularDepth,
                               int sensorPoint = -1);

class VplGatherer {
public:
    VplGatherer(const RenderScene& scene, const GatherSettings& settings);

    float maxG() const { return maxG_; }

    // Radiance along a camera ray; the VPL term is sum_i scale[i] * contribution_i (scale empty:
    // all 1). With sensorPoint >= 0 the ray is that point's of the scene's camera (what
    // Sensor::pointAt gives for its raster point), and for an irradiance sensor the light it
    // finds directly is shared with next-event estimation at the point (sensor_direct.h): the
    // value is then right for the point's block mean, not for the ray's own direction.
    Rgb radiance(const Ray& ray, SampleGenerator& rng, std::span<const Vpl> vpls, std::span<const float> scale = {},
                 int sensorPoint = -1) const;

    // radiance() in two parts that sum to it, drawing the same random numbers: the VPL term
    // (linear in the VPLs' powers) and the rest.
    struct Parts {
        Rgb vpl{0, 0, 0};
        Rgb rest{0, 0, 0};
    };
    Parts radianceParts(const Ray& ray, SampleGenerator& rng, std::span<const Vpl> vpls, int sensorPoint = -1) const;

    // Radiance leaving the receiver toward r.wo by reflection (its emission not included): direct
    // light, the clamp residual and the VPL term, as radiance() computes at x1. With
    // withoutDeltaLights, the direct light of point, spot, directional lights and luminaires is
    // left out (the caller adds it exactly); the rest stays unbiased.
    Rgb reflected(const VplReceiver& r, SampleGenerator& rng, std::span<const Vpl> vpls, std::span<const float> scale = {},
                  bool withoutDeltaLights = false) const;
    // reflected() in the two parts of radianceParts().
    Parts reflectedParts(const VplReceiver& r, SampleGenerator& rng, std::span<const Vpl> vpls, std::span<const float> scale = {},
                         bool withoutDeltaLights = false) const;

private:
    // Direct light at r (the mean of directSamples) and the clamp's residual; the residual's VPL
    // term goes to .vpl, the rest to .rest. With `vpls` empty the residual is traced as a path.
    Parts directAndResidual(const VplReceiver& r, SampleGenerator& rng, bool withoutDeltaLights, std::span<const Vpl> vpls,
                            std::span<const float> scale, int directSamples) const;
    // The clamp's residual as it is summed: the VPLs (and their scales) that estimate it at x2,
    // and the parts so far.
    struct Residual {
        std::span<const Vpl> vpls;
        std::span<const float> scale;
        Parts value;
    };
    // One sample of the direct light at r (next-event estimation and a BSDF sample); with
    // `residual`, that BSDF sample's estimate of the clamp's residual is added to it.
    Rgb directSample(const VplReceiver& r, const Frame& frame, const V3f& woLocal, SampleGenerator& rng, bool withoutDeltaLights,
                     Residual* residual) const;
    // The light leaving x2 toward x1 (x2 diffuse or glossy, not an emitter) as the gather
    // estimates it at x1, x2's own residual by a path.
    Parts leavingX2(const VplReceiver& x2, SampleGenerator& rng, std::span<const Vpl> vpls, std::span<const float> scale) const;

    const RenderScene& scene_;
    GatherSettings settings_;
    PathTracer pathTracer_;
    float maxG_;
};

}  // namespace lucerna
