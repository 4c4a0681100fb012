#pragma once
// What a calculation grid checks about its points before it trusts a method's figures:
//   - points inside closed geometry (in a cabinet, a partition, a desk top), where no work is done
//     and whose 0 lx would pull Emin and U0 to 0: left out of the figures (core/photometry/calculation_grid.h);
//   - points that a delta light (point, spot, luminaire, sun) reaches only through glass: no random
//     path reaches them (a delta light behind a delta interface), so a method whose direct light is
//     a shadow ray (path, ir, preview) reads 0 there with a 0 error bar it cannot back. The sensor
//     methods (bdpt, mir, mlt, cmlt) carry that light: the direct part through the panes
//     (thinPaneTransmittance), the rest on their light paths.

#include "render/photometry/grid_calculation.h"

#include <cstdint>
#include <vector>

namespace lucerna {

// Per point, 1 when it is inside closed geometry. The rule: of kInsideProbeRays directions spread
// over the hemisphere the grid measures (cosine-weighted, a fixed spiral), more than three
// quarters meet the back face of a surface (its normal pointing away from the point: the inside of
// a closed solid, or the underside of a one-sided sheet right above the point). A point in a
// room meets the walls' front faces, a point under a table its underside's front face; a few
// probes slipping out through a seam of a closed box do not change the answer.
inline constexpr int kInsideProbeRays = 64;
std::vector<uint8_t> pointsInsideGeometry(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal);

// Per point, 1 when a delta light that would light it (in front of its side) is hidden only by
// glass (dielectric surfaces) on the straight line to it.
std::vector<uint8_t> pointsLitThroughGlass(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal);

// Whether a method carries light that reaches a point only through glass from a delta light.
bool carriesLightThroughGlass(GridMethod method);

}  // namespace lucerna
