#pragma once
// The illuminance layer of an image (issue 7, EXR channel `illuminance.Y`): per pixel, the
// illuminance in lux (683 Y(E)) at the first diffuse or glossy surface the camera sees, through
// mirrors and glass, on the side the camera path arrives from. Pixel values are box-filtered as
// R, G, B are (SPEC.md section 3): each estimate follows a camera ray through a uniform point of
// the pixel, and the irradiance there is estimated by IrradianceEstimator (path). 0 where the
// camera sees no such surface (the sky, an emitter).

#include "core/task_system.h"
#include "render/trace/render_scene.h"

#include <vector>

namespace lucerna {

// `samplesPerPixel` estimates per pixel at the RenderScene's camera resolution, row-major from the
// top-left as Image::pixels. Cancellable between rows (the result is then incomplete: discard
// it); progress goes to ctx. Never throws.
std::vector<float> traceIlluminanceLayer(const RenderScene& scene, int samplesPerPixel, uint64_t seed,
                                         TaskContext& ctx);

}  // namespace lucerna
