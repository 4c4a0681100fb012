#include "render/trace/sensor_direct.h"

#include "render/trace/path_tracer.h"

namespace lucerna {

float sensorRayWeight(const RenderScene& scene, int point, const V3f& dir, const SurfacePoint* emitterHit) {
    const Sensor& sensor = scene.camera();
    if (sensor.isPinhole()) return 1.0f;
    const V3f p = sensor.position(point);
    const float lightPdf = emitterHit ? scene.lights().pdfEmitter(emitterHit->triangle, p, emitterHit->p, emitterHit->ng,
                                                                  sensor.normal(point))
                                      : scene.lights().pdfEnvironment(dir, p);
    return powerHeuristic(sensor.pdfDirection(point, dir), lightPdf);
}

Rgb sensorNextEvent(const RenderScene& scene, int point, SampleGenerator& rng) {
    const Sensor& sensor = scene.camera();
    if (sensor.isPinhole()) return Rgb(0, 0, 0);
    // The sensor's rays leave its position itself (SensorRender lifts points off surfaces), so
    // its shadow rays do too.
    SurfacePoint ref;
    ref.p = sensor.position(point);
    ref.pError = V3f(0, 0, 0);
    ref.ng = sensor.normal(point);
    ref.triangle = 0xffffffffu;  // no triangle: nothing is excluded from its rays
    const V2f u = rng.next2D();
    const float uSelect = rng.next1D();
    LightSample ls;
    if (!scene.lights().sample(ref, u, uSelect, ls, ref.ng) || ls.isDelta || !(ls.pdf > 0.0f)) return Rgb(0, 0, 0);
    const float rayPdf = sensor.pdfDirection(point, ls.wi);  // cos / pi: the block's response
    if (!(rayPdf > 0.0f)) return Rgb(0, 0, 0);
    const Rgb through = scene.transmittance(ls.shadowRay);  // glazing on the way
    if (isBlack(through)) return Rgb(0, 0, 0);
    // E / pi = int L cos / pi dw, estimated as L (cos / pi) / pdf.
    return ls.value * through * (rayPdf / ls.pdf * powerHeuristic(ls.pdf, rayPdf));
}

}  // namespace lucerna
