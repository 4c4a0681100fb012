#pragma once
// EN 12464-1's lighting requirements for indoor work places, and the check of a task area's
// figures against them (README, "Task areas").
//
// The bundled tables (lighting_standards.cpp) hold a selection of activities with their
// reference numbers, maintained illuminance Em (lx, on the task area's average), unified glare
// rating limit UGR_L, illuminance uniformity U0 and colour rendering index Ra, as EN 12464-1:2011
// tables 5.1 to 5.36 give them, and as the 2021 edition gives them with its additions: the
// context-modified Em,u, the mean cylindrical illuminance Ez (at 1.2 m seated, 1.6 m standing)
// and the average illuminance of the walls and of the ceiling, each with its uniformity. The
// 2021 entries keep the 2011 reference numbers (task areas name their activity by them); an
// activity the 2021 table does not hold is checked against its 2011 entry, and says so.

#include "core/photometry/calculation_grid.h"
#include "core/photometry/grid_error_bars.h"
#include "core/photometry/standard_edition.h"
#include "core/scene/scene.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lucerna {

struct ActivityRequirement {
    const char* reference;  // the table's reference number, "5.26.2" (2011's numbering in both editions)
    const char* area;       // "Offices"
    const char* activity;   // "Writing, typing, reading, data processing"
    double maintainedLux;   // Em: the area's average may not fall below it over the maintenance cycle
    double ugrLimit;        // UGR_L
    double uniformity;      // U0 = Emin / Eavg, at least
    double colourRendering; // Ra, at least
    StandardEdition edition = StandardEdition::En12464_2011;
    // 2021 only; 0 where the entry states none (not checked).
    double modifiedLux = 0;             // Em,u: the Em to design for where the context asks more (stated, not checked)
    double cylindricalLux = 0;          // Ez, mean over the activity area
    double cylindricalUniformity = 0;   // U0 of Ez
    double wallLux = 0;                 // Em of the walls
    double wallUniformity = 0;
    double ceilingLux = 0;              // Em of the ceiling
    double ceilingUniformity = 0;
};

// The edition's table. The 2021 table holds the entries it was checked for (README, "Task
// areas"); findActivity falls back to 2011 for the others.
std::span<const ActivityRequirement> en12464Activities(StandardEdition edition = StandardEdition::En12464_2011);
// The activity with this reference number in `edition`'s table, else in the 2011 table (its
// `edition` then says 2011); null when neither has it.
const ActivityRequirement* findActivity(const std::string& reference,
                                        StandardEdition edition = StandardEdition::En12464_2011);
// Every activity a task area may name when checked against `edition`, in the 2011 table's order,
// each as findActivity gives it: the 2021 entry where that table has one, else the 2011 entry
// (whose `edition` says so). For 2011: the 2011 table.
std::vector<const ActivityRequirement*> activitiesOf(StandardEdition edition);

// Met and NotMet only where the error bar cannot change the answer: a requirement within the
// achieved figure's error bar is Borderline. NotChecked: the figure is not the one the
// requirement is about (Em of a new installation, no maintenance factor) or its error is unknown.
enum class CheckOutcome { Met, Borderline, NotMet, NotStated, NotChecked };

// One requirement against what the design achieves.
struct RequirementCheck {
    // "Em", "U0", "UGR", "Ra"; 2021: "Ez", "U0,z", "Ewall", "U0,wall", "Eceiling", "U0,ceiling".
    // Quantities starting with E are lux, with U0 ratios.
    std::string quantity;
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

// Illuminance figures over a set of points (lux) and their error bars.
struct SurfaceIlluminance {
    GridStatistics grid;
    std::optional<GridErrorBars> errors;  // absent: the method backs no error bar
};

// What a task area achieves: the grid's figures (lux) and their error bars, the worst UGR over
// its observers (absent: not computed) and its error bar, the lowest Ra of the luminaires that
// light it (absent: some file does not state it), and whether the lux are maintained values
// (EN 12464-1's Em is maintained: without a maintenance factor it is not checked). The 2021
// figures, each absent when not computed: the cylindrical illuminance over the activity area,
// and the room's walls and ceiling.
struct TaskAreaFigures {
    GridStatistics grid;
    std::optional<GridErrorBars> gridErrors;  // absent: the method backs no error bar
    std::optional<double> worstUgr;
    std::optional<double> colourRendering;
    double worstUgrError = 0;
    bool maintainedValues = false;  // a maintenance factor applies, or no electric light is lit
    std::optional<SurfaceIlluminance> cylindrical, walls, ceiling;
};

// Whether lux figures may be checked as maintained values: a maintenance factor applies, or there
// is no electric light to maintain.
inline bool valuesAreMaintained(const MaintenanceRange& range) { return range.maintained() || !range.electric; }

// The Ra of the installation: the lowest Ra the files of the scene's luminaires (switched on)
// state; absent when any electric light states none (a point or spot light, an IES file, an
// emitter object) or there is none.
std::optional<double> statedColourRendering(const Scene& scene);

// The task area's requirement line: "EN 12464-1:2011 5.26.2, Offices: Writing, typing, ...:
// Em 500 lx, U0 0.60, UGR_L 19, Ra 80"; a 2021 entry adds its Em,u, Ez, walls and ceiling. When
// `asked` is 2021 and the entry is 2011's (the 2021 table lacks it), the line says so.
std::string describeRequirement(const ActivityRequirement& requirement,
                                std::optional<StandardEdition> asked = std::nullopt);

// Em, U0, UGR and Ra in that order; then, where the entry states them, Ez, U0,z, Ewall, U0,wall,
// Eceiling and U0,ceiling (the lux ones maintained values: not checked without a maintenance
// factor, as Em).
std::vector<RequirementCheck> checkRequirements(const ActivityRequirement& requirement, const TaskAreaFigures& figures);

// The modelling ratio Ez / Eh (EN 12464-1:2021, 5.2.6: between 0.30 and 0.60 for good
// modelling): guidance, never a requirement. Absent without both figures or with Eh = 0.
std::optional<double> modellingRatio(const TaskAreaFigures& figures);
// "modelling Ez/Eh 0.42 (guidance 0.30 to 0.60: within)", "... (guidance ...: below: flat)",
// "... above: harsh".
std::string describeModelling(double ratio);
inline constexpr double kModellingRatioLow = 0.30, kModellingRatioHigh = 0.60;

}  // namespace lucerna
