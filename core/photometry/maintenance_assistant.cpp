#include "core/photometry/maintenance_assistant.h"

#include "core/number_format.h"

#include <cmath>
#include <stdexcept>

namespace lucerna {

namespace {

// A factor as the explanations write it: three decimals at most, trailing zeros dropped.
std::string factorText(double v) {
    std::string s = fixedNumber(v, 3);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    return s;
}

std::string hoursText(double h) { return fixedNumber(h, 0) + " h"; }

std::string yearsText(double years) {
    const std::string n = factorText(years);
    return n + (n == "1" ? " year" : " years");
}

// "" at a column; " (between the 1 and 1.5 year columns)" between two.
std::string columnNote(const std::vector<double>& xs, double x, const std::string& unit) {
    for (size_t i = 0; i + 1 < xs.size(); ++i)
        if (x > xs[i] && x < xs[i + 1])
            return " (between the " + factorText(xs[i]) + " and " + factorText(xs[i + 1]) + unit + " columns)";
    return {};
}

void require(bool ok, const std::string& reason) {
    if (!ok) throw std::invalid_argument(reason);
}

void findLampFactors(const MaintenanceChoices& c, const Cie97Tables& tables, MaintenanceAssessment& a) {
    const std::string hours = hoursText(c.operatingHours);
    if (c.spotReplacement) a.lsf = {1.0, "LSF 1: failed lamps replaced at once (spot replacement; AS/NZS 1680.4:2017, 3.3)"};

    if (c.lamp == kLedLamp) {
        const double x = c.ledLumenFraction, life = c.ledRatedLifeHours;
        const std::string rating = "LED rated L" + fixedNumber(100 * x, 0) + " at " + hoursText(life);
        if (c.operatingHours <= life) {
            const double llmf = 1 - (1 - x) * c.operatingHours / life;
            a.llmf = {llmf, "LLMF " + factorText(llmf) + ": " + rating + ", " + hours +
                                " of operation; a straight line from 1 at 0 h through " + factorText(x) +
                                " at the rated life (common practice; take the maker's median, B50, rating)"};
        } else {
            a.llmf = {std::nullopt, "LLMF not found: " + hours + " is beyond the " + rating +
                                        " (the rating says nothing past it); take the maker's figure at " + hours};
        }
        if (!c.spotReplacement)
            a.lsf = {std::nullopt, "LSF not found: without spot replacement take the LED maker's failure rate at " +
                                       hours + " (LSF = 1 - the fraction failed)"};
        return;
    }
    if (c.lamp == kMakersDataLamp) {
        a.llmf = {std::nullopt, "LLMF not found: take the lamp maker's lumen maintenance at " + hours};
        if (!c.spotReplacement) a.lsf = {std::nullopt, "LSF not found: take the lamp maker's survival at " + hours};
        return;
    }
    const Cie97Tables::LampFamily* family = tables.findLamp(c.lamp);
    require(family, "unknown lamp \"" + c.lamp + "\" (expected " + kLedLamp + ", " + kMakersDataLamp +
                        " or a lamp family of the tables)");
    const std::string where = tables.source + ", " + family->name + " at " + hours +
                              columnNote(tables.lampHours, c.operatingHours, " h");
    if (const auto llmf = interpolateLinearly(tables.lampHours, family->llmf, c.operatingHours))
        a.llmf = {*llmf, "LLMF " + factorText(*llmf) + ": " + where};
    else
        a.llmf = {std::nullopt, "LLMF not found: " + hours + " is outside the table's hours; take the lamp maker's figure"};
    if (c.spotReplacement) return;
    if (const auto lsf = interpolateLinearly(tables.lampHours, family->lsf, c.operatingHours))
        a.lsf = {*lsf, "LSF " + factorText(*lsf) + ": " + where + ", group replacement"};
    else
        a.lsf = {std::nullopt, "LSF not found: " + hours + " is outside the table's hours; take the lamp maker's figure"};
}

void findLuminaireFactor(const MaintenanceChoices& c, const Cie97Tables& tables, MaintenanceAssessment& a) {
    const std::string what = std::string("type ") + luminaireClassName(c.luminaire) + ", " +
                             cleanlinessName(c.luminaireEnvironment) + ", cleaned every " +
                             yearsText(c.luminaireCleaningYears);
    const auto row = tables.lmf.find({c.luminaire, c.luminaireEnvironment});
    if (row == tables.lmf.end()) {
        a.lmf = {std::nullopt, "LMF not found: CIE 97:2005 Table 3 is not bundled with Lucerna; take the luminaire "
                               "maker's LMF (" + what + ")"};
        return;
    }
    if (const auto lmf = interpolateLinearly(tables.cleaningYears, row->second, c.luminaireCleaningYears))
        a.lmf = {*lmf, "LMF " + factorText(*lmf) + ": " + tables.source + " Table 3, " + what +
                           columnNote(tables.cleaningYears, c.luminaireCleaningYears, " year")};
    else
        a.lmf = {std::nullopt, "LMF not found: the table has no column for " + yearsText(c.luminaireCleaningYears)};
}

void findRoomFactor(const MaintenanceChoices& c, const Cie97Tables& tables, MaintenanceAssessment& a) {
    const std::string room = "K = " + fixedNumber(a.roomIndex, 2) + " (" + factorText(c.roomLengthM) + " x " +
                             factorText(c.roomWidthM) + " m, luminaires " + factorText(c.mountingHeightM) +
                             " m above the work plane)";
    const std::string what = std::string(distributionName(c.distribution)) + ", " + cleanlinessName(c.roomEnvironment) +
                             ", room cleaned every " + yearsText(c.roomCleaningYears);
    if (!tables.hasRsmf()) {
        a.rsmf = {std::nullopt, "RSMF not found: " + room + "; CIE 97:2005 Table 4 is not bundled with Lucerna; "
                                "take the standard's RSMF (" + what + ")"};
        return;
    }
    a.roomSize = roomSizeFor(a.roomIndex, tables);
    const auto row = tables.rsmf.find({a.roomSize, c.distribution, c.roomEnvironment});
    if (row == tables.rsmf.end()) {
        a.rsmf = {std::nullopt, "RSMF not found: the table has no row for a " + std::string(roomSizeName(a.roomSize)) +
                                    " room, " + what};
        return;
    }
    if (const auto rsmf = interpolateLinearly(tables.cleaningYears, row->second, c.roomCleaningYears))
        a.rsmf = {*rsmf, "RSMF " + factorText(*rsmf) + ": " + tables.source + " Table 4, " + room + ", a " +
                             roomSizeName(a.roomSize) + " room, " + what +
                             columnNote(tables.cleaningYears, c.roomCleaningYears, " year")};
    else
        a.rsmf = {std::nullopt, "RSMF not found: the table has no column for " + yearsText(c.roomCleaningYears)};
}

}  // namespace

const char* cleanlinessName(Cleanliness c) {
    switch (c) {
    case Cleanliness::VeryClean: return "very clean";
    case Cleanliness::Clean: return "clean";
    case Cleanliness::Normal: return "normal";
    case Cleanliness::Dirty: return "dirty";
    }
    return "";
}

const char* luminaireClassName(LuminaireClass c) {
    // CIE 97:2005's types as lighting handbooks name them; G as the standard defines it.
    switch (c) {
    case LuminaireClass::A: return "A (bare lamp)";
    case LuminaireClass::B: return "B (open top reflector)";
    case LuminaireClass::C: return "C (closed top reflector)";
    case LuminaireClass::D: return "D (enclosed, IP2X)";
    case LuminaireClass::E: return "E (dustproof, IP5X)";
    case LuminaireClass::F: return "F (indirect up-lighter)";
    case LuminaireClass::G: return "G";
    }
    return "";
}

const char* distributionName(LightDistribution d) {
    switch (d) {
    case LightDistribution::Direct: return "direct";
    case LightDistribution::DirectIndirect: return "direct/indirect";
    case LightDistribution::Indirect: return "indirect";
    }
    return "";
}

const char* roomSizeName(RoomSize s) {
    switch (s) {
    case RoomSize::Small: return "small";
    case RoomSize::Medium: return "medium";
    case RoomSize::Large: return "large";
    }
    return "";
}

const Cie97Tables::LampFamily* Cie97Tables::findLamp(const std::string& name) const {
    for (const LampFamily& f : lamps)
        if (f.name == name) return &f;
    return nullptr;
}

const Cie97Tables& bundledCie97Tables() {
    // CIE 97:2005 Tables 1 to 4 go here, with `source` naming the edition and its tables, once a
    // copy of the published figures can be checked (two sources agreeing): none could be when this
    // was written, and a table that might be wrong is worse than none for a maintained value.
    static const Cie97Tables tables = [] {
        Cie97Tables t;
        t.source = "CIE 97:2005";
        return t;
    }();
    return tables;
}

std::optional<MaintenanceFactor> MaintenanceAssessment::factors() const {
    MaintenanceFactor mf;
    mf.lampLumenMaintenance = llmf.value;
    mf.lampSurvival = lsf.value;
    mf.luminaireMaintenance = lmf.value;
    mf.roomSurfaceMaintenance = rsmf.value;
    if (!llmf.value && !lsf.value && !lmf.value && !rsmf.value) return std::nullopt;
    return mf;
}

double roomIndex(double lengthM, double widthM, double mountingHeightM) {
    require(lengthM > 0 && widthM > 0 && mountingHeightM > 0 && std::isfinite(lengthM * widthM * mountingHeightM),
            "the room's length, width and mounting height must be positive (m)");
    return lengthM * widthM / (mountingHeightM * (lengthM + widthM));
}

RoomSize roomSizeFor(double k, const Cie97Tables& tables) {
    RoomSize best = RoomSize::Small;
    double nearest = std::abs(k - tables.roomIndexOfSize[0]);
    for (size_t i = 1; i < 3; ++i)
        if (const double d = std::abs(k - tables.roomIndexOfSize[i]); d < nearest) {
            nearest = d;
            best = RoomSize(i);
        }
    return best;
}

std::optional<double> interpolateLinearly(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
    if (xs.empty() || xs.size() != ys.size() || !(x >= xs.front() && x <= xs.back())) return std::nullopt;
    for (size_t i = 0; i < xs.size(); ++i)
        if (x == xs[i]) return ys[i];
    for (size_t i = 0; i + 1 < xs.size(); ++i)
        if (x < xs[i + 1]) {
            const double t = (x - xs[i]) / (xs[i + 1] - xs[i]);
            return ys[i] + t * (ys[i + 1] - ys[i]);
        }
    return std::nullopt;
}

MaintenanceAssessment assessMaintenance(const MaintenanceChoices& c, const Cie97Tables& tables) {
    require(c.operatingHours > 0 && std::isfinite(c.operatingHours), "the operating hours must be positive");
    if (c.lamp == kLedLamp) {
        require(c.ledLumenFraction > 0 && c.ledLumenFraction < 1, "the LED's rating Lx must be between L1 and L99");
        require(c.ledRatedLifeHours > 0 && std::isfinite(c.ledRatedLifeHours), "the LED's rated life must be positive");
    }
    for (const double years : {c.luminaireCleaningYears, c.roomCleaningYears})
        require(years >= 0.5 && years <= 3, "a cleaning interval must be 0.5 to 3 years (CIE 97:2005's tables), not " +
                                                shortestNumber(years));
    MaintenanceAssessment a;
    a.roomIndex = roomIndex(c.roomLengthM, c.roomWidthM, c.mountingHeightM);
    findLampFactors(c, tables, a);
    findLuminaireFactor(c, tables, a);
    findRoomFactor(c, tables, a);
    return a;
}

}  // namespace lucerna
