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
//   - preview: white-receiver preview frames (render/preview/preview_illuminance.h).

#include "core/task_system.h"
#include "render/photometry/grid_calculation.h"
#include "render/trace/render_scene.h"

#include <map>
#include <string>
#include <vector>

namespace lucerna {

// The rows of the layer one process computes when several share it (a distributed render,
// render/backend/pooled_films.h): those whose index modulo `count` is `index`; the other rows
// stay 0, so that the processes' layers add up to the whole. path and ir then give what one
// process gives (each pixel's estimates depend on the pixel alone); bdpt, mir, mlt and cmlt
// render each process's sensors from a seed of its own (processSeed); the preview's layer is
// computed by index 0 alone.
struct RowShare {
    int index = 0, count = 1;
    bool owns(int row) const { return row % count == index; }
};

// `samplesPerPixel` estimates per pixel (path, ir), passes of the backend (bdpt, mir, mlt,
// cmlt) or frames (preview), at the RenderScene's camera resolution, row-major from the top-left
// as Image::pixels; `options` are the backend's (render's --option). Cancellable (the result is
// then incomplete: discard it); progress goes to ctx. Throws what a backend throws for a bad
// option or in prepare().
std::vector<float> traceIlluminanceLayer(const RenderScene& scene, GridMethod method, int samplesPerPixel,
                                         uint64_t seed, TaskContext& ctx,
                                         const std::map<std::string, std::string>& options = {},
                                         RowShare share = {});

}  // namespace lucerna
