#pragma once
// Veach's lens perturbation in path space (Veach 1997, section 11.4.3), the kernel of cmlt's
// path-space lens sub-chain (cmlt_chain.h).
//
// A path x_0 ... x_k (x_0 on the sensor, x_k on a light) is split at x_m, its first vertex that
// is not on a mirror or glass: x_1 ... x_{m-1} are specular, x_m scatters diffusely or glossily
// (or is the emitter itself, m = k). The perturbation moves the raster point and traces the new
// camera ray through the same specular chain (each vertex a mirror or glass again, reflecting or
// refracting as before) to a new y_m, then joins y_m to the unchanged x_{m+1} by a shadow ray;
// x_{m+1} ... x_k stay. Parameterised by (raster point, x_{m+1}, ..., x_k), the path's image
// contribution is F = P(r) f(y_m) G(y_m, x_{m+1}) f(x_{m+1}) R: P the specular chain's
// reflectances and Fresnel factors, R the fixed rest. With the raster step symmetric (a
// Gaussian on the image torus: lens_mutation.h), min(1, F(y) / F(x)) keeps F's density; a path
// of another structure (a specular vertex missed or added) has F = 0 and is rejected.
//
// Only the colour of R matters (a constant scale cancels from F(y) / F(x) and from the deposits
// C / F), so R is the product of the fixed vertices' BSDF colours and the light's.
//
// Where a mirror or glass follows x_m and the path goes on through specular vertices alone to an
// emitter (E S+ D S+ L, m >= 2: a caustic seen through glass or in a mirror), nothing can be
// joined; Veach's multi-chain perturbation keeps instead the direction w in which the path leaves
// x_m: from y_m the ray goes on along w through the same specular vertices and must hit an
// emitter. Parameterised by (raster point, w), F = P(r) f(y_m, w) |cos| P' Le.

#include "render/progressive/bdpt/bdpt_vertex.h"

#include <optional>
#include <vector>

namespace lucerna {

class LensPath {
public:
    LensPath(const RenderScene& scene, const VertexDensities& densities) : scene_(scene), densities_(densities) {}

    // Takes path x_0 ... x_k (SampledPaths::path). False when no perturbation can move it (x_{m+1}
    // on a mirror or glass and neither form above, or a directional light): its class holds this
    // path alone.
    bool build(const std::vector<PathVertex>& path);

    // The contribution (up to the constant scale of R) of the path of the same structure through
    // raster point (x, y) (pixels), whose camera ray's closest hit is `primaryHit`; black when
    // there is none (the structure differs, or y_m does not see x_{m+1}).
    Rgb contribution(float x, float y, const std::optional<SurfacePoint>& primaryHit) const;

private:
    bool buildKeepingDirection(const std::vector<PathVertex>& path);
    // The multi-chain form's factors from y_m on: f |cos| along w, the chain, the emitter's Le.
    Rgb alongDirection(const PathVertex& ym) const;

    const RenderScene& scene_;
    const VertexDensities& densities_;
    int m_ = 0;                   // the first non-specular vertex
    bool endsAtM_ = false;        // m = k: y_m must be an emitter
    bool nextIsLast_ = false;     // x_{m+1} = x_k: its factor is its emission toward y_m
    PathVertex next_;             // x_{m+1}; wo toward x_{m+2}
    std::vector<bool> refracted_; // per specular vertex 1 ... m-1
    Rgb rest_{1, 1, 1};           // R
    bool keepsDirection_ = false; // the multi-chain form: w kept, the chain x_{m+1} ... x_{k-1} traced
    V3f direction_{0, 0, 1};      // w
    std::vector<bool> lightSideRefracted_;  // per specular vertex m+1 ... k-1
};

}  // namespace lucerna
