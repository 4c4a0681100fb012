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
// Where a mirror or glass follows x_m, nothing can be joined there; Veach's multi-chain
// perturbation keeps instead the direction w_m in which the path leaves x_m: from y_m the ray goes
// on along w_m through the same specular vertices to the next vertex that is not specular, which
// must be an emitter (E S+ D S+ L, m >= 2: a caustic seen through glass or in a mirror; E D S+ L
// is the caustic perturbation's, path_caustic.h) or a diffuse or glossy y_n, from which the path
// is joined to x_{n+1} as above, or goes on along its kept w_n if a mirror or glass follows x_n
// too. Parameterised by (raster point, w_m, w_n, ..., the fixed rest), each kept direction
// contributes f(y_a, w_a) |cos(y_a, w_a)| P_a: the generalised geometric term through a specular
// chain times the Jacobian of the area at its end against w_a's solid angle is the cosine at
// y_a. The directions do not move, so the step stays symmetric.

#include "render/progressive/bdpt/bdpt_vertex.h"

#include <optional>
#include <vector>

namespace lucerna {

class LensPath {
public:
    LensPath(const RenderScene& scene, const VertexDensities& densities) : scene_(scene), densities_(densities) {}

    // Takes path x_0 ... x_k (SampledPaths::path). False when no perturbation can move it (a
    // specular chain from x_1 straight to the light, a specular chain ending at a point or
    // directional light, a directional light joined): its class holds this path alone.
    bool build(const std::vector<PathVertex>& path);

    // The contribution (up to the constant scale of R) of the path of the same structure through
    // raster point (x, y) (pixels), whose camera ray's closest hit is `primaryHit`; black when
    // there is none (the structure differs, or y_m does not see x_{m+1}).
    Rgb contribution(float x, float y, const std::optional<SurfacePoint>& primaryHit) const;

private:
    // A kept direction (the multi-chain form): the ray leaves y_a along w and crosses the
    // specular vertices a+1 ... n-1, each reflecting or refracting as before.
    struct KeptDirection {
        V3f w{0, 0, 1};
        std::vector<bool> refracted;
    };

    bool buildJoin(const std::vector<PathVertex>& path, int n);
    // f |cos| P along each kept direction from y (y_m), which moves to the vertex that ends the
    // last chain: the emitter, whose Le is included, or the diffuse y_n, whose join is left to
    // the caller. Black when a chain does not reach a vertex of the path's kind.
    Rgb alongKeptDirections(PathVertex& y) const;
    // `before` times f(y_n) G(y_n, x_{n+1}) f(x_{n+1}) R if y_n sees x_{n+1}, else black.
    Rgb joined(const PathVertex& yn, const Rgb& before) const;

    const RenderScene& scene_;
    const VertexDensities& densities_;
    int m_ = 0;                   // the first non-specular vertex
    bool endsAtM_ = false;        // m = k: y_m must be an emitter
    bool endsAtSky_ = false;      // x_k is the environment: the path's last edge leaves the scene
    std::vector<bool> refracted_; // per specular vertex 1 ... m-1
    std::vector<KeptDirection> kept_;  // the multi-chain form's kept directions, in path order
    bool keptEndsAtEmitter_ = false;   // the last kept direction's chain ends at the emitter x_k
    // The join from the last diffuse vertex y_n (n = m without kept directions) to x_{n+1}.
    bool nextIsLast_ = false;     // x_{n+1} = x_k: its factor is its emission toward y_n
    PathVertex next_;             // x_{n+1}; wo toward x_{n+2}
    Rgb rest_{1, 1, 1};           // R: x_{n+2} ... x_k
};

}  // namespace lucerna
