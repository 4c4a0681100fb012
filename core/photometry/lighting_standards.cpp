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

// Figures as a designer reads them: lux to the unit, U0 to two places, UGR to one.
std::string figure(const std::string& quantity, double x) {
    if (quantity == "Em") return fixedNumber(x, 0) + " lx";
    if (quantity == "U0") return fixedNumber(x, 2);
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
    const double unit = quantity == "U0" ? 0.01 : quantity == "UGR" ? 0.1 : 1.0;
    if (error >= 0.5 * unit) return figure(quantity, error);
    char digits[32];
    std::snprintf(digits, sizeof digits, "%.1g", error);
    return std::string(digits) + (quantity == "Em" ? " lx" : "");
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

}  // namespace

std::span<const ActivityRequirement> en12464Activities() { return kActivities; }

const ActivityRequirement* findActivity(const std::string& reference) {
    for (const ActivityRequirement& a : kActivities)
        if (reference == a.reference) return &a;
    return nullptr;
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
    if (quantity == "Em" && required > 0)
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

std::string describeRequirement(const ActivityRequirement& r) {
    return std::string("EN 12464-1:2011 ") + r.reference + ", " + r.area + ": " + r.activity + ": Em " +
           fixedNumber(r.maintainedLux, 0) + " lx, U0 " + fixedNumber(r.uniformity, 2) + ", UGR_L " +
           fixedNumber(r.ugrLimit, 0) + ", Ra " + fixedNumber(r.colourRendering, 0);
}

std::vector<RequirementCheck> checkRequirements(const ActivityRequirement& requirement, const TaskAreaFigures& figures) {
    const std::optional<GridErrorBars>& bars = figures.gridErrors;
    RequirementCheck em = check("Em", requirement.maintainedLux, false, figures.grid.average,
                                bars ? std::optional(bars->average) : std::nullopt);
    if (em.achieved && !figures.maintainedValues) {
        em.outcome = CheckOutcome::NotChecked;
        em.notCheckedBecause = "no maintenance factor (Em is maintained; these are values of the new installation)";
    }
    return {em,
            check("U0", requirement.uniformity, false, figures.grid.uniformity,
                  bars ? std::optional(bars->uniformity) : std::nullopt),
            check("UGR", requirement.ugrLimit, true, figures.worstUgr, figures.worstUgrError),
            check("Ra", requirement.colourRendering, false, figures.colourRendering, 0.0)};
}

}  // namespace lucerna
