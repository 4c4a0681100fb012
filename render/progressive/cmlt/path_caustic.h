#pragma once
// Veach's caustic perturbation in path space (Veach 1997, section 11.4.4), for the paths the lens
// perturbation cannot move (path_lens.h) because a mirror or glass follows their first diffuse
// vertex: x_0 (the sensor), x_1 (diffuse or glossy), x_2 ... x_{k-1} (mirrors and glass), x_k (a
// light), k >= 3: a caustic seen directly.
//
// The emission direction at x_k turns by a small random rotation (perturbDirection) and the new
// ray is traced through the same specular vertices (each reflecting or refracting as before) to a
// new y_1, which is joined to the same sensor point. Parameterised by x_k and the direction w
// there, the path's image contribution is that of a light-tracing splat without its densities,
//   F = Le(x_k, w) |cos_k| P f(y_1) |cos_1| We cos / d^2,
// P the specular chain's reflectances and Fresnel factors: the flux of a pencil of directions
// spreads over y_1's area, which G's area measure takes back, so no Jacobian through the chain
// is needed. With the rotation symmetric, min(1, F(y) / F(x)) keeps F's density; each candidate
// deposits at its own raster point.

#include "render/progressive/bdpt/bdpt_vertex.h"
#include "render/trace/rng.h"

#include <vector>

namespace lucerna {

// w turned by an angle of Rayleigh distribution (scale sigma, radians) about a uniform azimuth:
// a density in w' that depends on the angle between w and w' alone, so T(w, w') = T(w', w).
V3f perturbDirection(const V3f& w, float sigma, Rng& rng);

class CausticPath {
public:
    CausticPath(const RenderScene& scene, const VertexDensities& densities) : scene_(scene), densities_(densities) {}

    // Takes path x_0 ... x_k (SampledPaths::path). False when it is not of the form above (or
    // its light is directional, whose direction cannot turn).
    bool build(const std::vector<PathVertex>& path);
    // The built path's emission direction at x_k.
    const V3f& direction() const { return direction_; }

    // The contribution of the path of the same structure leaving x_k along unit w, and the
    // raster point it lands on; black when there is none.
    Rgb contribution(const V3f& w, float& rasterX, float& rasterY) const;

private:
    const RenderScene& scene_;
    const VertexDensities& densities_;
    PathVertex light_;             // x_k
    int sensorPoint_ = 0;          // x_0's
    std::vector<bool> refracted_;  // x_{k-1} ... x_2, in the order the light's ray meets them
    V3f direction_{0, 0, 1};
};

}  // namespace lucerna
