#pragma once
// The light that reaches an irradiance sensor's point straight from an emitter or the sky
// (sensor.h), found two ways and combined by the power heuristic (Veach 1997, section 9.2): by
// the sensor's own rays, drawn with density cos / pi, which find a bright sky's broad patches
// well; and by next-event estimation at the point, which finds the sun's disc and small
// luminaires that a cosine-distributed ray almost never meets (a sunlit point of the daylit
// office: about one sensor ray in 70 000 sees the sun, which gives nine tenths of the light
// there). A pinhole keeps its rays alone: a pixel measures what its ray sees.
//
// Every backend that renders sensors as cameras weighs what its sensor rays find directly by
// sensorRayWeight and adds sensorNextEvent to the sample of the same point; what a sensor ray
// finds through a mirror or glass, which no shadow ray follows, keeps weight 1.

#include "render/trace/render_scene.h"
#include "render/trace/sample_generator.h"

namespace lucerna {

// The weight of light that a ray of sensor point `point` found without scattering: leaving the
// scene along `dir` (unit; emitterHit null) or at the front of the emitter at *emitterHit. 1 for
// the pinhole.
float sensorRayWeight(const RenderScene& scene, int point, const V3f& dir, const SurfacePoint* emitterHit);

// Next-event estimation's share of the direct light at sensor point `point`, in the units of
// the point's pixels (radiance; their mean over the point's block is E / pi): one light sample,
// three numbers from rng. Delta lights give nothing (the sensor's users add them exactly, as
// sensor.h says). Black for the pinhole, which draws no numbers.
Rgb sensorNextEvent(const RenderScene& scene, int point, SampleGenerator& rng);

}  // namespace lucerna
