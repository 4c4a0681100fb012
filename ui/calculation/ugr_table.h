#pragma once
// The calculation dock's table of a UGR grid (render/photometry/ugr_grid.h): a cell per observer,
// coloured by its UGR.

#include "core/photometry/calculation_grid.h"
#include "render/photometry/glare_evaluation.h"

#include <QColor>

class QTableWidget;

namespace lucerna {

// The colour of a UGR value: the false-colour ramp from 10 (blue) to 30 (red), linear.
QColor ugrColour(double ugr);
// The table of a UGR grid, rows from the far side as the illuminance table (a dash and grey
// where no luminaire is in the field of view), tooltips with the error bar, Lb and the strongest
// source.
void fillUgrTable(QTableWidget& table, const GridLayout& layout, const GlareGridResult& result);

}  // namespace lucerna
