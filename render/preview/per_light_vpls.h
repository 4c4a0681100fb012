#pragma once
// VPL generation for the preview, one set per light so that editing one light regenerates only
// its set. Light particles are traced with Embree through the render scene; a VPL is stored at
// every diffuse or glossy hit (the light that arrived there), so the sets stand for indirect
// light only: the preview draws direct light itself, with shadow maps.
//
// The particles are traced by the shared instant-radiosity tracer (render/vpl/instant_radiosity.h,
// traceLightPath); this file only drives it per light from the preview's own copy of the lights,
// so that an edited light needs no new RenderScene (no BVH rebuild).

#include "core/scene.h"
#include "render/trace/light_sampler.h"
#include "render/trace/render_scene.h"
#include "render/vpl/vpl.h"

namespace lucerna {

// A light sampler over exactly one light: a delta light, or all emissive triangles together.
LightSampler singleLightSampler(const RenderScene& scene, const DeltaLight* delta);

// Traces light paths from `source` until `count` VPLs are stored (or a path budget of 64 count
// runs out), keeps exactly `count` of them (a uniform choice, powers scaled to make up) and
// divides by the number of paths traced, so the set's sum estimates the light's indirect
// contribution. Deterministic in seed.
VplSet traceVpls(const RenderScene& scene, const LightSampler& source, int count, uint64_t seed, int maxBounces = 8);

}  // namespace lucerna
