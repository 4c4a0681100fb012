#include "core/photometry/lighting_standards.h"

#include "core/photometry/goniometric_distribution.h"
#include "core/number_format.h"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace lucerna {

namespace {

// EN 12464-1:2011, tables 5.1 to 5.36 (a selection): reference, area, activity, Em (lx), UGR_L,
// U0, Ra.
constexpr ActivityRequirement kActivities[] = {
    {"5.1.1", "Traffic zones inside buildings", "Circulation areas and corridors", 100, 28, 0.40, 40},
    {"5.1.2", "Traffic zones inside buildings", "Stairs, escalators, travolators", 100, 25, 0.40, 40},
    {"5.1.3", "Traffic zones inside buildings", "Elevators, lifts", 100, 25, 0.40, 40},
    {"5.1.4", "Traffic zones inside buildings", "Ramps, loading bays", 150, 25, 0.40, 40},
    {"5.2.1", "Rest, sanitation and first aid rooms", "Canteens, pantries", 200, 22, 0.40, 80},
    {"5.2.2", "Rest, sanitation and first aid rooms", "Rest rooms", 100, 22, 0.40, 80},
    {"5.2.3", "Rest, sanitation and first aid rooms", "Rooms for physical exercise", 300, 22, 0.40, 80},
    {"5.2.4", "Rest, sanitation and first aid rooms", "Cloakrooms, washrooms, bathrooms, toilets", 200, 25, 0.40, 80},
    {"5.2.5", "Rest, sanitation and first aid rooms", "Sick bay", 500, 19, 0.60, 80},
    {"5.2.6", "Rest, sanitation and first aid rooms", "Rooms for medical attention", 500, 16, 0.60, 90},
    {"5.3.1", "Control rooms", "Plant rooms, switch gear rooms", 200, 25, 0.40, 60},
    {"5.3.2", "Control rooms", "Telex, post room, switchboard", 500, 19, 0.60, 80},
    {"5.4.1", "Store rooms, cold stores", "Store and stock rooms", 100, 25, 0.40, 60},
    {"5.26.1", "Offices", "Filing, copying, etc.", 300, 19, 0.40, 80},
    {"5.26.2", "Offices", "Writing, typing, reading, data processing", 500, 19, 0.60, 80},
    {"5.26.3", "Offices", "Technical drawing", 750, 16, 0.70, 80},
    {"5.26.4", "Offices", "CAD work stations", 500, 19, 0.60, 80},
    {"5.26.5", "Offices", "Conference and meeting rooms", 500, 19, 0.60, 80},
    {"5.26.6", "Offices", "Reception desk", 300, 22, 0.60, 80},
    {"5.26.7", "Offices", "Archives", 200, 25, 0.40, 80},
    {"5.27.1", "Retail premises", "Sales area", 300, 22, 0.40, 80},
    {"5.27.2", "Retail premises", "Till area", 500, 19, 0.60, 80},
    {"5.27.3", "Retail premises", "Wrapping table", 500, 19, 0.60, 80},
    {"5.36.1", "Educational buildings", "Play school, nursery", 300, 22, 0.40, 80},
    {"5.36.2", "Educational buildings", "Handicraft rooms", 300, 19, 0.60, 80},
    {"5.36.3", "Educational buildings", "Classrooms, tutorial rooms", 300, 19, 0.60, 80},
    {"5.36.4", "Educational buildings", "Classrooms for evening classes and adult education", 500, 19, 0.60, 80},
    {"5.36.5", "Educational buildings", "Auditorium, lecture halls", 500, 19, 0.60, 80},
    {"5.36.6", "Educational buildings", "Black, green and white boards", 500, 19, 0.70, 80},
    {"5.36.12", "Educational buildings", "Technical drawing rooms", 750, 16, 0.70, 80},
    {"5.36.17", "Educational buildings", "Libraries: bookshelves", 200, 19, 0.60, 80},
    {"5.36.18", "Educational buildings", "Libraries: reading areas", 500, 19, 0.60, 80},
};

// EN 12464-1:2021, the entries a public summary of its tables states in full (README, "Task
// areas"), keyed by the 2011 reference numbers of the same activity: reference, area, activity,
// Em (lx), UGR_L, U0, Ra, then Em,u, Ez, U0 of Ez, Em of the walls, their U0, Em of the ceiling,
// its U0. The standard's own text was not to hand; the sources below give no 2021 table number.
// Their tables put "U0 >= 0,10" over the Ez, wall and ceiling columns (the general clause's
// uniformity), and "-" where an activity has no Ez, wall or ceiling figure (0 here: not checked).
// Each activity the sources do not state in full is left to its 2011 entry.
constexpr ActivityRequirement kActivities2021[] = {
    // Glamox, "Einzelbüros" and "Grossraumbüros", "Beleuchtungsanforderungen gemäss EN 12464-1:2021":
    // https://test.glamox.com/de-ch/pbs/Lichtloesungen/buero/einzelbueros
    // https://test.glamox.com/de-ch/pbs/Lichtloesungen/buero/grossraumbueros
    // (Em,u 1000 lx also in https://www.hildiberg.is, on the draft prEN 12464-1.) The table adds that
    // in a small cellular office the wall figure is for the front wall, at least 75 lx on the others.
    {"5.26.2", "Offices", "Writing, typing, reading, data processing", 500, 19, 0.60, 80,
     StandardEdition::En12464_2021, 1000, 150, 0.10, 150, 0.10, 100, 0.10},
    // Glamox, "Tagungs- und Konferenzräume" ("Konferenz- und Sitzungsräume"; "Konferenztisch" alike):
    // https://test.glamox.com/de-ch/pbs/Lichtloesungen/buero/tagungs-konferenzraeume
    {"5.26.5", "Offices", "Conference and meeting rooms", 500, 19, 0.60, 80,
     StandardEdition::En12464_2021, 1000, 150, 0.10, 150, 0.10, 100, 0.10},
    // Glamox, "Bibliotheken" ("Bibliothek: Bücherregale", the vertical illuminance on the shelves;
    // Ez, walls and ceiling "-"):
    // https://test.glamox.com/de/pbs/beleuchtungsloesungen/bildungswesen/bibliotheken-hoersaele
    {"5.36.17", "Educational buildings", "Libraries: bookshelves", 200, 19, 0.60, 80,
     StandardEdition::En12464_2021, 300},
};

bool isLux(const std::string& quantity) { return !quantity.empty() && quantity[0] == 'E'; }
bool isUniformity(const std::string& quantity) { return quantity.rfind("U0", 0) == 0; }

// Figures as a designer reads them: lux to the unit, U0 to two places, UGR to one.
std::string figure(const std::string& quantity, double x) {
    if (isLux(quantity)) return fixedNumber(x, 0) + " lx";
    if (isUniformity(quantity)) return fixedNumber(x, 2);
    return fixedNumber(x, quantity == "UGR" ? 1 : 0);
}

// Met only when the margin exceeds the error bar, not met only when it falls short by more; an
// exact figure (no error bar) that equals the requirement meets it.
CheckOutcome judge(double margin, double error) {
    if (margin > error || (error == 0 && margin >= 0)) return CheckOutcome::Met;
    return margin < -error ? CheckOutcome::NotMet : CheckOutcome::Borderline;
}

// An error bar to the figure's precision, or to one significant digit where that would read 0.
std::string errorFigure(const std::string& quantity, double error) {
    const double unit = isUniformity(quantity) ? 0.01 : quantity == "UGR" ? 0.1 : 1.0;
    if (error >= 0.5 * unit) return figure(quantity, error);
    char digits[32];
    std::snprintf(digits, sizeof digits, "%.1g", error);
    return std::string(digits) + (isLux(quantity) ? " lx" : "");
}

RequirementCheck check(const std::string& quantity, double required, bool upperLimit, std::optional<double> achieved,
                       std::optional<double> error) {
    RequirementCheck c;
    c.quantity = quantity;
    c.required = required;
    c.upperLimit = upperLimit;
    c.achieved = achieved;
    if (!achieved) return c;
    c.margin = upperLimit ? required - *achieved : *achieved - required;
    c.error = error.value_or(0);
    if (!error) {
        c.outcome = CheckOutcome::NotChecked;
        c.notCheckedBecause = "error bar unknown";
        return c;
    }
    c.outcome = judge(c.margin, c.error);
    return c;
}

// A lux figure that EN 12464-1 states as maintained: not checked on values of the new installation.
void requireMaintained(RequirementCheck& c, bool maintainedValues) {
    if (!c.achieved || maintainedValues) return;
    c.outcome = CheckOutcome::NotChecked;
    c.notCheckedBecause = "no maintenance factor (" + c.quantity +
                          " is maintained; these are values of the new installation)";
}

// The lux and uniformity checks of one surface's figures (absent: not computed).
void checkSurface(std::vector<RequirementCheck>& checks, const std::string& lux, const std::string& uniformity,
                  double requiredLux, double requiredUniformity, const std::optional<SurfaceIlluminance>& s,
                  bool maintainedValues) {
    const std::optional<GridErrorBars>& bars = s ? s->errors : std::nullopt;
    if (requiredLux > 0) {
        checks.push_back(check(lux, requiredLux, false, s ? std::optional(s->grid.average) : std::nullopt,
                               bars ? std::optional(bars->average) : std::nullopt));
        requireMaintained(checks.back(), maintainedValues);
    }
    if (requiredUniformity > 0)
        checks.push_back(check(uniformity, requiredUniformity, false,
                               s ? std::optional(s->grid.uniformity) : std::nullopt,
                               bars ? std::optional(bars->uniformity) : std::nullopt));
}

}  // namespace

const char* standardEditionName(StandardEdition edition) {
    return edition == StandardEdition::En12464_2021 ? "EN 12464-1:2021" : "EN 12464-1:2011";
}

std::optional<StandardEdition> standardEditionFromName(const std::string& name) {
    for (StandardEdition e : {StandardEdition::En12464_2011, StandardEdition::En12464_2021})
        if (name == standardEditionName(e)) return e;
    return std::nullopt;
}

std::span<const ActivityRequirement> en12464Activities(StandardEdition edition) {
    if (edition == StandardEdition::En12464_2021) return kActivities2021;
    return kActivities;
}

const ActivityRequirement* findActivity(const std::string& reference, StandardEdition edition) {
    for (const ActivityRequirement& a : en12464Activities(edition))
        if (reference == a.reference) return &a;
    if (edition != StandardEdition::En12464_2011) return findActivity(reference, StandardEdition::En12464_2011);
    return nullptr;
}

std::vector<const ActivityRequirement*> activitiesOf(StandardEdition edition) {
    std::vector<const ActivityRequirement*> list;
    for (const ActivityRequirement& a : kActivities) list.push_back(findActivity(a.reference, edition));
    return list;
}

std::string RequirementCheck::outcomeWord() const {
    switch (outcome) {
    case CheckOutcome::Met: return "met";
    case CheckOutcome::Borderline: return "borderline";
    case CheckOutcome::NotMet: return "not met";
    case CheckOutcome::NotChecked: return "not checked";
    case CheckOutcome::NotStated: break;
    }
    return quantity == "Ra" ? "not stated" : "not computed";
}

std::string RequirementCheck::describe() const {
    const std::string bound = std::string(upperLimit ? "<= " : ">= ") + figure(quantity, required);
    if (!achieved) return quantity + " " + outcomeWord() + " (" + bound + " required)";
    std::string line = quantity + " " + figure(quantity, *achieved);
    if (error > 0) line += " +- " + errorFigure(quantity, error);
    line += " " + bound + ": " + outcomeWord();
    if (outcome == CheckOutcome::NotChecked) return line + ": " + notCheckedBecause;
    line += " (margin " + std::string(margin >= 0 ? "+" : "") + figure(quantity, margin);
    if (isLux(quantity) && required > 0)
        line += ", " + std::string(margin >= 0 ? "+" : "") + fixedNumber(100 * margin / required, 1) + "%";
    if (outcome == CheckOutcome::Borderline) line += ", within the error bar";
    return line + ")";
}

std::optional<double> statedColourRendering(const Scene& scene) {
    std::optional<double> lowest;
    for (const Light& l : scene.lights) {
        if (!l.on || l.type == LightType::Sun || l.type == LightType::Directional) continue;
        const auto& d = l.luminaire ? l.luminaire->distribution : nullptr;
        if (!d || !d->colourRenderingIndex) return std::nullopt;
        lowest = std::min(lowest.value_or(*d->colourRenderingIndex), *d->colourRenderingIndex);
    }
    for (const Object& o : scene.objects) {
        const Material* m = scene.findMaterial(o.material);
        if (m && m->type == MaterialType::Emitter) return std::nullopt;
    }
    return lowest;
}

std::string describeRequirement(const ActivityRequirement& r, std::optional<StandardEdition> asked) {
    std::string line = std::string(standardEditionName(r.edition)) + " " + r.reference + ", " + r.area + ": " +
                       r.activity + ": Em " + fixedNumber(r.maintainedLux, 0) + " lx";
    if (r.modifiedLux > 0) line += " (Em,u " + fixedNumber(r.modifiedLux, 0) + " lx)";
    line += ", U0 " + fixedNumber(r.uniformity, 2) + ", UGR_L " + fixedNumber(r.ugrLimit, 0) + ", Ra " +
            fixedNumber(r.colourRendering, 0);
    const auto surface = [&](const char* name, double lux, double u0) {
        if (lux > 0) line += std::string(", ") + name + " " + fixedNumber(lux, 0) + " lx";
        if (u0 > 0) line += " (U0 " + fixedNumber(u0, 2) + ")";
    };
    surface("Ez", r.cylindricalLux, r.cylindricalUniformity);
    surface("Ewall", r.wallLux, r.wallUniformity);
    surface("Eceiling", r.ceilingLux, r.ceilingUniformity);
    if (asked && *asked != r.edition)
        line += std::string(" (") + standardEditionName(*asked) + " asked; its table here lacks this activity)";
    return line;
}

std::vector<RequirementCheck> checkRequirements(const ActivityRequirement& requirement, const TaskAreaFigures& figures) {
    const std::optional<GridErrorBars>& bars = figures.gridErrors;
    RequirementCheck em = check("Em", requirement.maintainedLux, false, figures.grid.average,
                                bars ? std::optional(bars->average) : std::nullopt);
    requireMaintained(em, figures.maintainedValues);
    std::vector<RequirementCheck> checks{
        em,
        check("U0", requirement.uniformity, false, figures.grid.uniformity,
              bars ? std::optional(bars->uniformity) : std::nullopt),
        check("UGR", requirement.ugrLimit, true, figures.worstUgr, figures.worstUgrError),
        check("Ra", requirement.colourRendering, false, figures.colourRendering, 0.0)};
    const bool maintained = figures.maintainedValues;
    checkSurface(checks, "Ez", "U0,z", requirement.cylindricalLux, requirement.cylindricalUniformity,
                 figures.cylindrical, maintained);
    checkSurface(checks, "Ewall", "U0,wall", requirement.wallLux, requirement.wallUniformity, figures.walls,
                 maintained);
    checkSurface(checks, "Eceiling", "U0,ceiling", requirement.ceilingLux, requirement.ceilingUniformity,
                 figures.ceiling, maintained);
    return checks;
}

std::optional<double> modellingRatio(const TaskAreaFigures& figures) {
    if (!figures.cylindrical || !(figures.grid.average > 0)) return std::nullopt;
    return figures.cylindrical->grid.average / figures.grid.average;
}

std::string describeModelling(double ratio) {
    const char* where = ratio < kModellingRatioLow    ? "below: flat"
                        : ratio > kModellingRatioHigh ? "above: harsh"
                                                      : "within";
    return "modelling Ez/Eh " + fixedNumber(ratio, 2) + " (guidance " + fixedNumber(kModellingRatioLow, 2) + " to " +
           fixedNumber(kModellingRatioHigh, 2) + ": " + where + ")";
}

}  // namespace lucerna
