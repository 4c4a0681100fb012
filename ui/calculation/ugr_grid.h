#pragma once
// The calculation dock's UGR grid (README, "Glare (UGR)"): an observer at each point of the grid,
// at eye height above the floor, all looking the same way along the grid's edges; what the
// table, the figures and the CSV show of their UGR (render/photometry/glare_evaluation.h).

#include "core/photometry/calculation_grid.h"
#include "render/photometry/glare_evaluation.h"

#include <QColor>
#include <QString>
#include <QStringList>

#include <string>
#include <vector>

class QTableWidget;

namespace lucerna {

// The view of a UGR grid along one of its edges.
enum class GridViewDirection { PlusU, MinusU, PlusV, MinusV };
V3d gridViewDirection(const CalculationGrid& grid, GridViewDirection direction);

// The eyes over the grid's points: each point moved to eyeHeightM above floorY (scene units).
std::vector<V3d> observerPositions(const GridLayout& layout, double floorY, double metersPerUnit, double eyeHeightM);

// The colour of a UGR value: the false-colour ramp from 10 (blue) to 30 (red), linear.
QColor ugrColour(double ugr);
// The table of a UGR grid, rows from the far side as the illuminance table (a dash and grey
// where no luminaire is in the field of view), tooltips with the error bar, Lb and the strongest
// source.
void fillUgrTable(QTableWidget& table, const GridLayout& layout, const GlareGridResult& result);
// The figures: the highest and lowest UGR and where, the background's range, the error bar.
QStringList ugrFigures(const GlareGridResult& result, const GridLayout& layout, double eyeHeightM, const QString& view);
// i,j,x,y,z (the eye, scene units),ugr,error,background_cd_m2 per observer; empty fields where
// no luminaire is in the field of view.
std::string ugrCsv(const GridLayout& layout, const std::vector<V3d>& eyes, const GlareGridResult& result);

}  // namespace lucerna
