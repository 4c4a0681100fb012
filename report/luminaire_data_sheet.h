#pragma once
// The luminaire data sheets of a report (README, "Reports"): one per luminaire type of the
// schedule (a photometric file at one flux and luminous area), with what the file states (name,
// flux, power, efficacy, CCT, Ra, luminous opening), its distribution for the polar diagram in
// cd/klm, and its UGR table by CIE 117's tabular method in CIE 190's layout
// (core/photometry/ugr_table.h, as `lucerna glare --table` prints it). Point and spot lights and
// emitting objects have no file: no data sheet.

#include "core/photometry/glare.h"
#include "core/photometry/goniometric_distribution.h"
#include "core/photometry/ugr_table.h"
#include "core/scene/scene.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lucerna {

struct Schedule;

struct LuminaireDataSheet {
    std::string product;   // the file's luminaire name (empty: none stated)
    std::string file;      // as the scene names it
    int count = 0;         // lights of this type switched on
    double lumensEach = 0; // as installed (new: no maintenance factor), lm
    std::shared_ptr<const GoniometricDistribution> distribution;
    // What the file states: the luminaire's flux (its table's integral, lm), input power (W),
    // CCT (K), Ra; absent: not stated.
    double fileLumens = 0;
    std::optional<double> watts, temperatureK, colourRenderingIndex;
    std::optional<double> sceneTemperatureK;  // the colour the scene gives the lights, when a temperature
    // The file's lumens per watt (its flux over its power); absent without a power.
    std::optional<double> efficacy() const;
    // cd/klm per candela of the file's table: 1000 / its flux.
    double cdPerKlmPerTableCd() const;

    LuminousArea luminousArea;     // UGR's: the scene's luminous_area key or the file's opening
    bool luminousAreaFromScene = false;
    // UGR tables at spacing-to-height 1 and 0.25 for lumensEach; empty when they cannot be made
    // (no luminous area, no flux), with the reason in ugrMissing.
    std::vector<UgrTable> ugr;
    std::string ugrMissing;
};

// One data sheet per luminaire type among `schedule`'s lines of scene `scene` (as loaded, the
// files read): lines of the same file, flux each and luminous area share one (a different
// maintenance factor or colour does not make another type). In the schedule's order.
std::vector<LuminaireDataSheet> luminaireDataSheets(const Scene& scene, const Schedule& schedule);

}  // namespace lucerna
