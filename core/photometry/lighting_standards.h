#pragma once
// EN 12464-1's lighting requirements for indoor work places, and the check of a task area's
// figures against them (README, "Task areas").
//
// The bundled table (lighting_standards.cpp) holds a selection of activities with their
// reference numbers, maintained illuminance Em (lx, on the task area's average), unified glare
// rating limit UGR_L, illuminance uniformity U0 and colour rendering index Ra, as EN 12464-1:2011
// tables 5.1 to 5.36 give them. The 2021 edition renumbers the tables and adds "modified"
// values for some contexts; a design for it should be checked against the edition in force.

#include "core/photometry/calculation_grid.h"
#include "core/photometry/grid_error_bars.h"
#include "core/scene/scene.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lucerna {

struct ActivityRequirement {
    const char* reference;  // the table's reference number, "5.26.2"
    const char* area;       // "Offices"
    const char* activity;   // "Writing, typing, reading, data processing"
    double maintainedLux;   // Em: the area's average may not fall below it over the maintenance cycle
    double ugrLimit;        // UGR_L
    double uniformity;      // U0 = Emin / Eavg, at least
    double colourRendering; // Ra, at least
};

std::span<const ActivityRequirement> en12464Activities();
// The activity with this reference number; null when the table has none.
const ActivityRequirement* findActivity(const std::string& reference);

// Met and NotMet only where the error bar cannot change the answer: a requirement within the
// achieved figure's error bar is Borderline. NotChecked: the figure is not the one the
// requirement is about (Em of a new installation, no maintenance factor) or its error is unknown.
enum class CheckOutcome { Met, Borderline, NotMet, NotStated, NotChecked };

// One requirement against what the design achieves.
struct RequirementCheck {
    std::string quantity;           // "Em", "U0", "UGR", "Ra"
    double required = 0;
    bool upperLimit = false;        // UGR: achieved at most `required`; the others at least
    std::optional<double> achieved; // absent: not stated (Ra) or not computed (UGR)
    double error = 0;               // the achieved figure's 95% error bar (0: exact, as Ra)
    CheckOutcome outcome = CheckOutcome::NotStated;
    std::string notCheckedBecause;  // NotChecked: "no maintenance factor", "error bar unknown"
    // Achieved minus required for a lower bound, required minus achieved for UGR: positive
    // when met, in the quantity's unit.
    double margin = 0;

    // One line: "Em 512 lx +- 4 lx >= 500 lx: met (margin +12 lx, +2.4%)", "UGR 19.0 +- 0.1
    // <= 19: borderline (margin +0.0 within the error bar)", "Ra not stated (>= 80 required)".
    std::string describe() const;
    // "met", "borderline", "not met", "not stated", "not computed", "not checked".
    std::string outcomeWord() const;
};

// What a task area achieves: the grid's figures (lux) and their error bars, the worst UGR over
// its observers (absent: not computed) and its error bar, the lowest Ra of the luminaires that
// light it (absent: some file does not state it), and whether the lux are maintained values
// (EN 12464-1's Em is maintained: without a maintenance factor it is not checked).
struct TaskAreaFigures {
    GridStatistics grid;
    std::optional<GridErrorBars> gridErrors;  // absent: the method backs no error bar
    std::optional<double> worstUgr;
    std::optional<double> colourRendering;
    double worstUgrError = 0;
    bool maintainedValues = false;  // a maintenance factor applies, or no electric light is lit
};

// Whether lux figures may be checked as maintained values: a maintenance factor applies, or there
// is no electric light to maintain.
inline bool valuesAreMaintained(const MaintenanceRange& range) { return range.maintained() || !range.electric; }

// The Ra of the installation: the lowest Ra the files of the scene's luminaires (switched on)
// state; absent when any electric light states none (a point or spot light, an IES file, an
// emitter object) or there is none.
std::optional<double> statedColourRendering(const Scene& scene);

// The task area's requirement line: "EN 12464-1:2011 5.26.2, Offices: Writing, typing, ...:
// Em 500 lx, U0 0.60, UGR_L 19, Ra 80".
std::string describeRequirement(const ActivityRequirement& requirement);

// Em, U0, UGR and Ra in that order.
std::vector<RequirementCheck> checkRequirements(const ActivityRequirement& requirement, const TaskAreaFigures& figures);

}  // namespace lucerna
