#pragma once
// A UGR grid (README, "Glare (UGR)"): an observer at each point of a horizontal calculation grid
// (core/photometry/calculation_grid.h), at eye height above the floor, all looking the same way
// along the grid's edges; their UGR (glare_evaluation.h, evaluateGlareGrid) as figures and as
// CSV. Shown by the calculation dock (ui/calculation/grid_panel.h); Qt-free, so that the command
// line can write one as well.

#include "core/photometry/calculation_grid.h"
#include "render/photometry/glare_evaluation.h"

#include <string>
#include <vector>

namespace lucerna {

// The view of a UGR grid along one of its edges.
enum class GridViewDirection { PlusU, MinusU, PlusV, MinusV };
V3d gridViewDirection(const CalculationGrid& grid, GridViewDirection direction);
// The view in words: "along -v, toward (0, 0, 1)".
std::string describeGridView(const CalculationGrid& grid, GridViewDirection direction);

// The eyes over the grid's points: each point moved to eyeHeightM above floorY (scene units).
std::vector<V3d> observerPositions(const GridLayout& layout, double floorY, double metersPerUnit, double eyeHeightM);

// The figures, a line each: how many observers and how they look (`view`, describeGridView's),
// the highest and lowest UGR and where (column and row as a table shows them, rows from the far
// side down), the background's range, the error bar, and how many see no luminaire.
std::vector<std::string> ugrGridFigures(const GlareGridResult& result, const GridLayout& layout, double eyeHeightM,
                                        const std::string& view);

// i,j,x,y,z (the eye, scene units),ugr,error,background_cd_m2 per observer; empty fields where
// no luminaire is in the field of view.
std::string ugrCsv(const GridLayout& layout, const std::vector<V3d>& eyes, const GlareGridResult& result);

}  // namespace lucerna
