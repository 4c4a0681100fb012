#pragma once
// Particles leaving the lights, for light tracing, bidirectional methods and VPLs: area lights
// by uniform position and cosine direction, point lights uniformly over the sphere, spots
// uniformly over their cone, luminaires by their distribution (GoniometricSampler), directional
// lights and the environment from a disc of the scene's radius facing them, outside the scene.
//
// Units: every backend works in scene units. A delta light's intensity is divided by
// meters_per_unit^2 at emission (SPEC.md's E = I cos / (d mpu)^2 with d in scene units), so that
// the flux of any particle, from any light, is in W per scene-unit^2 of the scene's area measure
// and the geometric term cos cos / d^2 stays in scene units everywhere.

#include "render/trace/lights/daylight_portals.h"
#include "render/trace/lights/delta_light.h"
#include "render/trace/lights/emitter_triangle.h"
#include "render/trace/lights/environment_light.h"
#include "render/trace/surface_point.h"

#include <cstdint>

namespace lucerna {

struct EmissionSample {
    V3f position{0, 0, 0};
    V3f normal{0, 0, 0};     // the emitter's front normal; the direction itself for delta lights
    V3f direction{0, 0, 0};  // unit, leaving the light
    Rgb power{0, 0, 0};      // Le cos / (pdfPosition pdfDirection) or its delta-light equivalent
    float pdfPosition = 0;   // area measure, light selection included (1 per selection for delta positions)
    float pdfDirection = 0;  // solid angle (0 for the directional light's delta direction)
    bool deltaPosition = false, deltaDirection = false;
    uint32_t triangle = 0xffffffffu;  // the emissive triangle, if any
    SurfacePoint surface() const;     // the point on an area light, for spawning the first ray
    V3f pError{0, 0, 0};              // error bound of position (area lights)
    uint32_t light = 0;               // which light, numbered as LightSample::light
    bool environment = false;         // from the environment: position is on a disc outside the scene
};

// Each fills `out`, as EmissionSample() leaves it, with a particle from its light chosen with
// probability selectPdf, for uPosition and uDirection in [0, 1)^2; false where none leaves
// (a direction the light does not send to, nothing drawn). The scene's bounding sphere
// (sceneCenter, sceneRadius) places the discs of the lights at infinity.
bool emitFromTriangle(const EmitterTriangle& e, float selectPdf, const V2f& uPosition, const V2f& uDirection,
                      EmissionSample& out);
// With `portals` (not empty), a directional light's particles too travel along lines drawn
// through the windows (DaylightPortals::sampleParallel); pdfPosition is that line's density.
bool emitFromDeltaLight(const DeltaLight& l, float selectPdf, float metersPerUnit, const V3f& sceneCenter,
                        float sceneRadius, const V2f& uPosition, const V2f& uDirection, EmissionSample& out,
                        const DaylightPortals* portals = nullptr);
// With `portals` (not empty), the environment's particles travel along lines drawn through the
// windows as daylight_portals.h says; pdfPosition times pdfDirection is then their joint density
// (pdfDirection the environment's own, pdfPosition DaylightPortals::lineDensity's).
bool emitFromEnvironment(const EnvironmentLight& environment, float selectPdf, const V3f& sceneCenter,
                         float sceneRadius, const V2f& uPosition, const V2f& uDirection, EmissionSample& out,
                         const DaylightPortals* portals = nullptr);

}  // namespace lucerna
