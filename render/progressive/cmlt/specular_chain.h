#pragma once
// The specular chains of cmlt's path-space perturbations (path_lens.h, path_caustic.h): a
// perturbed ray must cross the same mirrors and glass as the path it perturbs, each taking the
// branch the path took there.

#include "render/progressive/bdpt/bdpt_vertex.h"

#include <vector>

namespace lucerna {

// Whether the path refracts at its vertex j (0 < j < the last): its neighbours lie on opposite
// sides of the surface.
bool refractedAt(const std::vector<PathVertex>& path, int j);

// Continues `ray` from `hit` the way the recorded branch went (reflected, or refracted) and
// multiplies `throughput` by that branch's factor in path space: the mirror's reflectance, glass's
// Fresnel reflectance or transmittance. False when the surface there is not a mirror or glass, or
// cannot take that branch (total internal reflection where the path refracted).
bool followSpecular(const RenderScene& scene, const SurfacePoint& hit, bool refracted, Ray& ray, Rgb& throughput);

}  // namespace lucerna
