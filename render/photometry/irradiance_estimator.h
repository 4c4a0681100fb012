#pragma once
// Irradiance at a point, for calculation grids and the illuminance layer: the light arriving on
// one side of a small oriented sensor, E = int L_i(w) cos(theta) dw over the hemisphere of its
// normal (W/m^2 per channel; independent of meters_per_unit, as SPEC.md says of irradiance from
// emitters). Illuminance in lux is 683 * Y(E).
//
// A white Lambertian surface (albedo 1) at the point reflects L_o = E / pi whatever the
// incident light, so E = pi L_o, and every estimator of reflected radiance the backends have
// becomes an estimator of irradiance by putting that surface there:
//   - Path: next-event estimation and a cosine-sampled continuation traced by the path
//     tracer, combined by the power heuristic (the path backend's estimator).
//   - Vpl: the same direct light, plus the indirect light gathered from a VPL set with the clamp
//     and its path-traced residual (the ir backend's estimator; vpl_gatherer.h).
// Both are unbiased for any point: on a surface (the floor) or in free space (a work plane).
// Both sum the direct light of every delta light exactly (one shadow ray each) rather than
// choosing one light at random: in a room lit by a few spots, the choice is most of the variance
// of a point's illuminance.

#include "render/trace/path_tracer.h"
#include "render/trace/render_scene.h"
#include "render/trace/rng.h"
#include "render/vpl/vpl_gatherer.h"

#include <span>

namespace lucerna {

// The fraction of light a shadow ray carries through the glass on its way: 1 when nothing
// blocks it, 0 when anything but a dielectric does, else the product over the dielectric
// interfaces it crosses of 1 - F (exact Fresnel at each crossing's angle), the ray going on
// straight. For a pane with parallel faces this is the light that arrives less its
// inter-reflections (a further (1 + R^2) factor, 0.2% at normal incidence for n = 1.5) and the
// pane's sideways shift of the ray (of the order of its thickness: negligible a lamp's distance
// away); for curved glass (a lens, a bulb) it is not the light that arrives.
float thinPaneTransmittance(const RenderScene& scene, const Ray& shadowRay);

class IrradianceEstimator {
public:
    explicit IrradianceEstimator(const RenderScene& scene, const GatherSettings& gather = {});

    // One sample of E at the sensor by path tracing. The delta lights' part, exact and the same
    // in every sample, is `deltaE` when given (deltaLightsIrradiance() at this sensor, computed
    // once: a floor of 10,000 lamps costs 10,000 shadow rays a point, not a sample), else
    // computed here.
    Rgb samplePath(const IrradianceSensor& sensor, Rng& rng, const Rgb* deltaE = nullptr) const;
    // One sample of E at the sensor: direct light and the clamp residual by path tracing, the
    // indirect light from `vpls` (an unbiased VPL set, instant_radiosity.h); `deltaE` as above.
    Rgb sampleVpl(const IrradianceSensor& sensor, Rng& rng, std::span<const Vpl> vpls,
                  const Rgb* deltaE = nullptr) const;
    // E at the sensor from the delta lights alone, exactly (one shadow ray each): what a sensor
    // rendered by a backend misses (sensor.h). With throughPanes, a shadow ray that meets only
    // glass passes, scaled by thinPaneTransmittance (the sensor methods' answer to a lamp behind
    // a window, which no random path can reach: a delta light seen through a delta interface).
    Rgb deltaLightsIrradiance(const IrradianceSensor& sensor, bool throughPanes = false) const;
    // The delta lights' cylindrical irradiance at `position` about `axis` (EN 12464-1's Ez: the
    // irradiance on a small vertical cylinder, that is the mean over azimuths of the irradiance
    // on a vertical plane), exactly: each light's irradiance normal to its direction times
    // sin(theta) / pi, theta its angle from the axis. throughPanes as above.
    Rgb deltaLightsCylindrical(const V3f& position, const V3f& axis, bool throughPanes = false) const;
    // The sensor moved off a surface it may lie on, along its normal, by more than the error
    // bound of a surface point there: a position a backend's rays can start from.
    IrradianceSensor lifted(const IrradianceSensor& sensor) const;

private:
    VplReceiver receiver(const IrradianceSensor& sensor) const;
    // Error bound of a point of this scene's surfaces near p (per axis).
    float errorBound(const V3f& p) const;
    // Radiance the white surface reflects toward its normal from all delta lights together.
    Rgb deltaLightsReflected(const VplReceiver& r, bool throughPanes = false) const;
    // Sum over the delta lights that reach r of the white albedo times their value times
    // response(wi) (wi toward the light), with glazing on the way as above.
    template <class Response>
    Rgb deltaLightsWeighted(const VplReceiver& r, bool throughPanes, const Response& response) const;

    const RenderScene& scene_;
    ShadingMaterial white_;
    PathTracer pathTracer_;
    VplGatherer gatherer_;
    float errorScale_;  // for ray offsets: the magnitude of the scene's coordinates
};

}  // namespace lucerna
