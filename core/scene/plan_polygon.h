#pragma once
// Polygons in plan (x, z), as a room's outline is drawn: their area and orientation, whether one
// crosses itself, where a point lies, and their triangulation by ear clipping. No library in the
// stack triangulates a non-convex polygon (OpenMesh's triangulate() fans each face from its first
// corner, which is wrong for an L-shaped room; Qt's triangulator is private), so it is here.

#include "core/math.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace lucerna {

using PlanPolygon = std::vector<V2d>;  // corners (x, z) in order, the last joined to the first

// The signed area (scene units squared), positive when the corners run counter-clockwise with x to the
// right and z up (clockwise as the plan view draws it, z down).
double signedArea(const PlanPolygon& polygon);

// Why the polygon cannot be a room's outline, in a few words ("wall 2 has no length", "walls 1
// and 3 cross", "fewer than 3 corners", "it encloses no area"); nothing when it is a simple
// polygon. Walls are the edges: wall k runs from corner k-1 to corner k (1-based; the last wall
// back to the first corner). Adjacent walls may run straight on, not double back.
std::optional<std::string> outlineProblem(const PlanPolygon& polygon);

// Whether the point lies inside the polygon (on its boundary counts as inside).
bool containsPoint(const PlanPolygon& polygon, const V2d& point);

// Whether two simple polygons share some area or touch (an edge of one crosses the other's, or
// one lies inside the other).
bool polygonsOverlap(const PlanPolygon& a, const PlanPolygon& b);

// Triangles (corner indices) covering a simple polygon (outlineProblem() says none), each turning
// the same way as the polygon; corners on a straight run between their neighbours form no
// triangle of their own. Ear clipping: O(n^2) for the few corners of a room.
std::vector<std::array<int, 3>> triangulate(const PlanPolygon& polygon);

}  // namespace lucerna
