#pragma once
// How the viewport draws the lights over its picture, apart from any widget so that it can be
// tested: a ball per light that shrinks with distance as a real object would (to a few pixels far
// away), none for a light behind the camera or too near it to draw, and none outside the picture;
// and for the selected lights a line along the aim, as far as the aim ray meets the scene, with
// a length cap. Picking (ui/viewport/light_pick.h) takes a light only where its symbol is drawn.

#include "ui/viewport/light_gizmo.h"

#include <QLineF>

#include <optional>

namespace lucerna {

struct LightSymbol {
    QPointF centre;  // widget pixels
    double radius;   // widget pixels
};

// World radius of a light's ball (a small luminaire), and its screen radius's bounds in pixels.
inline constexpr double kSymbolRadiusM = 0.1;
inline constexpr double kSmallestSymbolPx = 2.0, kLargestSymbolPx = 7.0;
// Lights nearer the camera than this along the view (the near plane) are not drawn: their ball
// would cover the picture, and anything drawn from them would sweep across it.
inline constexpr double kNearPlaneM = 0.2;
// The longest aim line, where the aim ray meets nothing nearer.
inline constexpr double kLongestAimLineM = 6.0;

// Depth of the near plane in scene units.
double nearPlaneDepth(double metersPerUnit);
// Depth of a world point along the view (scene units; negative behind the camera).
double depthAlongView(const ViewMapping& view, const V3d& world);

// The symbol of `light` seen through `view` (a scene of `metersPerUnit`): its projected centre and
// the screen size of a kSymbolRadiusM ball there, clamped to [smallest, largest] pixels. Nothing
// for a light at infinity (directional, sun), in front of the near plane or behind the camera, or
// whose centre is outside the picture.
std::optional<LightSymbol> lightSymbol(const Light& light, const ViewMapping& view, double metersPerUnit,
                                       double smallestPx = kSmallestSymbolPx, double largestPx = kLargestSymbolPx);

// The world segment a to b on screen, cut where it passes in front of the near plane at depth
// `nearDepth` (scene units along the view); nothing when all of it is in front.
std::optional<QLineF> projectedSegment(const ViewMapping& view, const V3d& a, const V3d& b, double nearDepth);

// How far a light's aim line reaches from its position (scene units): to where the aim ray first
// meets a surface (`hitDistance`, nothing when it meets none), at most kLongestAimLineM.
double aimLineLength(std::optional<double> hitDistance, double metersPerUnit);

}  // namespace lucerna
