#pragma once
// What one VPL contributes to a surface point (the formula of vpl.h), with the geometric term
// clamped: G = |cos_x| |cos_y| / d^2 is singular where a VPL nears the shaded point, so the
// gatherers use min(G, maxG) and estimate the clamped-away part, (G - maxG)^+, separately
// (Kollig & Keller 2004; see render/vpl/vpl_gatherer.h). The CPU backends gather with it and
// it is the CPU reference of the preview's shader.

#include "render/trace/render_scene.h"
#include "render/vpl/vpl.h"

#include <limits>
#include <span>

namespace lucerna {

inline constexpr float kNoClamp = std::numeric_limits<float>::infinity();

// The bound on G for a clamp distance given as a fraction of the scene's bounding radius (scale
// invariant: the same fraction clamps the same way at any meters_per_unit or scene size). A VPL
// facing the point head-on is clamped closer than fraction * radius. 0 or less: no clamp.
float geometricClampBound(const RenderScene& scene, float fractionOfRadius);

// The shaded point: where, what material, and the direction the light leaves toward (unit, from x).
struct VplReceiver {
    SurfacePoint x;
    const ShadingMaterial* material = nullptr;
    V3f wo;
};

// Radiance leaving x toward wo due to the VPL, with G clamped to maxG, visibility excluded.
// 0 where either side's BSDF is 0 (wrong side, black, emitter). Always finite.
Rgb vplContributionUnshadowed(const RenderScene& scene, const Vpl& vpl, const VplReceiver& r, float maxG);

// True when nothing blocks the segment between x and the VPL (shadow ray offset at both ends).
Rgb vplTransmittance(const RenderScene& scene, const Vpl& vpl, const SurfacePoint& x);

// vplContributionUnshadowed times visibility (the shadow ray is traced only when the rest is
// non-zero).
Rgb vplContribution(const RenderScene& scene, const Vpl& vpl, const VplReceiver& r, float maxG);

// Sum over a set, each VPL's contribution multiplied by scale[i] (all 1 when scale is empty).
// When perVpl is non-empty, it receives each VPL's luminance contribution (added, unscaled).
Rgb gatherVpls(const RenderScene& scene, std::span<const Vpl> vpls, std::span<const float> scale,
               const VplReceiver& r, float maxG, std::span<double> perVpl = {});

}  // namespace lucerna
