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

// Per point, 1 when it is inside geometry or on a surface, whichever way the faces point.
// Inside: more than three quarters of kInsideProbeRays directions spread over the hemisphere the
// grid measures (cosine-weighted, a fixed spiral) cross one object's surface an odd number of
// times (a few probes slipping out through a seam do not change the answer; a cabinet without a
// bottom encloses the upper hemisphere as well as a closed one), and that object is a solid: it
// does not enclose a light or the camera in the same way (a ceiling over the room, a room
// modelled as a closed box with outward faces) nor most of a work plane of four points or more
// (a daylit room seen from outside). On a surface: more than an eighth of the probes meet one
// within 1e-4 of the scene's radius (a grid point on a cabinet's face, whose estimate would be
// half inside the cabinet).
inline constexpr int kInsideProbeRays = 64;
std::vector<uint8_t> pointsInsideGeometry(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal);

// Per point, 1 when a delta light that would light it (in front of its side) is hidden only by
// glass (dielectric surfaces) on the straight line to it.
std::vector<uint8_t> pointsLitThroughGlass(const RenderScene& scene, const std::vector<V3d>& points, const V3d& normal);

// Whether a method carries light that reaches a point only through glass from a delta light.
bool carriesLightThroughGlass(GridMethod method);

}  // namespace lucerna
