#pragma once
// The per-thread part of the path backend: the radiance along one camera ray, by unidirectional
// path tracing with next-event estimation, multiple importance sampling of light and BSDF samples
// (power heuristic, Veach 1997) and Russian roulette.

#include "render/trace/path_settings.h"
#include "render/trace/render_scene.h"
#include "render/trace/sample_generator.h"

namespace lucerna {

class PathTracer {
public:
    PathTracer(const RenderScene& scene, const PathSettings& settings) : scene_(scene), settings_(settings) {}

    // How the ray to trace was chosen, when it continues a path from a non-specular vertex at
    // `origin` that sampled it with solid-angle pdf `pdf`: an emitter it hits is then weighted
    // against next-event estimation done at `origin` (power heuristic), not counted whole.
    struct ScatteredFrom {
        V3f origin;
        float pdf = 0;
        V3f receiving{0, 0, 0};  // the `receiving` normal next-event estimation used at origin
    };

    // Radiance arriving at the camera along `ray` (W sr^-1 m^-2 per channel); with `from`, the
    // radiance arriving at from->origin along the ray, MIS-weighted as the continuation of a path
    // that did next-event estimation there.
    Rgb radiance(Ray ray, SampleGenerator& rng, const ScatteredFrom* from = nullptr) const;

private:
    Rgb nextEventEstimate(const SurfacePoint& hit, const ShadingMaterial& mat, const Frame& frame, const V3f& woLocal,
                          SampleGenerator& rng) const;

    const RenderScene& scene_;
    PathSettings settings_;
};

// Power heuristic with beta = 2.
inline float powerHeuristic(float pdfA, float pdfB) {
    const float a = pdfA * pdfA, b = pdfB * pdfB;
    return a > 0.0f ? a / (a + b) : 0.0f;
}

}  // namespace lucerna
