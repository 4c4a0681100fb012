#pragma once
// The illuminance layer of an image (issue 7, EXR channel `illuminance.Y`): per pixel, the
// illuminance in lux (683 Y(E)) at the first diffuse or glossy surface the camera sees, through
// mirrors and glass, on the side the camera path arrives from; 0 where the camera sees no such
// surface (the sky, an emitter). Estimated by the machinery of the render's backend:
//   - path, ir: box-filtered as R, G, B are (SPEC.md section 3): each estimate follows a camera
//     ray through a uniform point of the pixel to its surface, where IrradianceEstimator (the
//     path or the VPL estimator, one fresh VPL set per estimate index) measures E.
//   - bdpt, mir, mlt, cmlt: the surface behind each pixel's centre becomes an irradiance sensor
//     and the backend renders all of them together (sensor_render.h); one point per pixel, not
//     box-filtered.
//   - preview: white-receiver preview frames (preview.h, previewIlluminanceLayer).

#include "core/task_system.h"
#include "render/photometry/grid_calculation.h"
#include "render/trace/render_scene.h"

#include <map>
#include <string>
#include <vector>

namespace lucerna {

// `samplesPerPixel` estimates per pixel (path, ir), passes of the backend (bdpt, mir, mlt,
// cmlt) or frames (preview), at the RenderScene's camera resolution, row-major from the top-left
// as Image::pixels; `options` are the backend's (render's --option). Cancellable (the result is
// then incomplete: discard it); progress goes to ctx. Throws what a backend throws for a bad
// option or in prepare().
std::vector<float> traceIlluminanceLayer(const RenderScene& scene, GridMethod method, int samplesPerPixel,
                                         uint64_t seed, TaskContext& ctx,
                                         const std::map<std::string, std::string>& options = {});

}  // namespace lucerna
