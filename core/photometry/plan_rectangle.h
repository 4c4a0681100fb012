#pragma once
// A calculation grid as a designer lays it out in a plan (README, "Task areas"): a horizontal
// rectangle with its sides along x and z, at a height y, facing up.

#include "core/photometry/calculation_grid.h"

#include <optional>

namespace lucerna {

struct PlanRectangle {
    double x0 = 0, z0 = 0;         // the corner of least x and z, scene units
    double width = 1, depth = 1;   // along x and along z, scene units, positive
    double y = 0;                  // the plane's height, scene units
    bool operator==(const PlanRectangle&) const = default;
};

// The rectangle of a horizontal grid whose edges lie along x and z (either way round, facing up
// or down); nothing for any other grid (on a wall, turned in the plan).
std::optional<PlanRectangle> planRectangle(const CalculationGrid& grid);

// The grid of a plan rectangle as workPlaneGrid lays one out: u along +x, v along -z, so that
// it faces up. The name and spacing are `like`'s.
CalculationGrid gridOfPlanRectangle(const PlanRectangle& r, const CalculationGrid& like = {});

}  // namespace lucerna
