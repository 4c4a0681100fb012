#pragma once
// CIE 97:2005's maintenance factor from what a designer knows (README, "Maintained values"):
// MF = LLMF x LSF x LMF x RSMF, each factor found from the lamp and its hours, the luminaire and
// its cleaning, and the room and its cleaning, with one line saying where it came from.
//
// - LED: LLMF from the rating Lx at a rated life (L80 at 50,000 h: 80% of the flux is left at
//   50,000 h), linear from 1 at 0 h, as is commonly done (a straight line through the rated point;
//   not a table of the standard, and not beyond the rated life, where the rating says nothing).
//   LSF 1 with spot replacement (failed LEDs replaced at once, AS/NZS 1680.4:2017, 3.3).
// - Lamp families (CIE 97:2005 Tables 1 and 2), LMF (Table 3) and RSMF (Table 4) come from
//   tables of factors by operating hours or by cleaning interval, linearly interpolated between
//   the tabulated columns. The tables are data (Cie97Tables); the set bundled with Lucerna
//   (bundledCie97Tables) holds none of them yet: no copy of the published tables could be checked
//   (README, "Maintained values"), so those factors are reported not found, with what to take
//   instead, until the tables are filled in.
// - The room index K = L W / (h (L + W)) (h: the luminaires' height above the work plane) picks
//   Table 4's room column (small, medium, large).
//
// Pure C++; no Qt.

#include "core/scene/scene.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace lucerna {

// CIE 97:2005's environments: how much dirt the air carries.
enum class Cleanliness { VeryClean, Clean, Normal, Dirty };
// CIE 97:2005's luminaire types A to G (LMF, Table 3).
enum class LuminaireClass { A, B, C, D, E, F, G };
// The lighting's distribution (RSMF, Table 4).
enum class LightDistribution { Direct, DirectIndirect, Indirect };
// Table 4's room columns, by room index.
enum class RoomSize { Small, Medium, Large };

// "very clean", "clean", "normal", "dirty".
const char* cleanlinessName(Cleanliness c);
// "A (bare lamp)", ..., "G".
const char* luminaireClassName(LuminaireClass c);
// "direct", "direct/indirect", "indirect".
const char* distributionName(LightDistribution d);
// "small", "medium", "large".
const char* roomSizeName(RoomSize s);

// The lamp choices besides the families of Cie97Tables::lamps: an LED by its rating, and any
// lamp whose LLMF and LSF the designer takes from its maker's data.
inline constexpr const char* kLedLamp = "LED";
inline constexpr const char* kMakersDataLamp = "lamp maker's data";

// What the designer knows. Hours are operating hours between group replacements (or to the end
// of the maintenance period); lengths in metres; cleaning intervals in years, 0.5 to 3.
struct MaintenanceChoices {
    std::string lamp = kLedLamp;     // kLedLamp, kMakersDataLamp or a family name of the tables
    double ledLumenFraction = 0.8;   // LED: x of its rating Lx (L80: 0.8), in (0, 1)
    double ledRatedLifeHours = 50000;
    double operatingHours = 12000;
    bool spotReplacement = true;     // failed lamps replaced at once: LSF 1

    LuminaireClass luminaire = LuminaireClass::D;
    Cleanliness luminaireEnvironment = Cleanliness::Clean;
    double luminaireCleaningYears = 1;

    double roomLengthM = 10, roomWidthM = 8;
    double mountingHeightM = 2;      // the luminaires above the work plane
    LightDistribution distribution = LightDistribution::Direct;
    Cleanliness roomEnvironment = Cleanliness::Clean;
    double roomCleaningYears = 1;
};

// Factors by cleaning interval and by operating hours as CIE 97:2005 tabulates them. Every row
// has one value per column of its table. Empty parts are simply not offered.
struct Cie97Tables {
    std::string source;  // the citation the explanations give, e.g. "CIE 97:2005"

    // Tables 1 and 2: LLMF and LSF of lamp families at operating hours.
    struct LampFamily {
        std::string name;  // "fluorescent triphosphor"
        std::vector<double> llmf, lsf;
    };
    std::vector<double> lampHours;  // ascending
    std::vector<LampFamily> lamps;

    // Tables 3 and 4 share the cleaning-interval columns (years, ascending).
    std::vector<double> cleaningYears;
    std::map<std::pair<LuminaireClass, Cleanliness>, std::vector<double>> lmf;
    // Table 4's rooms: the room index each column stands for, small to large.
    std::array<double, 3> roomIndexOfSize{};
    std::map<std::tuple<RoomSize, LightDistribution, Cleanliness>, std::vector<double>> rsmf;

    bool hasLmf() const { return !lmf.empty(); }
    bool hasRsmf() const { return !rsmf.empty(); }
    const LampFamily* findLamp(const std::string& name) const;
};

// The tables bundled with Lucerna (see the header's comment: none of CIE 97's are, yet).
const Cie97Tables& bundledCie97Tables();

// One factor as found: its value (absent: not found, the explanation says what to take instead)
// and one line saying where it came from.
struct FoundFactor {
    std::optional<double> value;
    std::string explanation;
};

struct MaintenanceAssessment {
    FoundFactor llmf, lsf, lmf, rsmf;
    double roomIndex = 0;
    RoomSize roomSize = RoomSize::Medium;  // meaningful with a Table 4

    // The factors found, as the scene keeps them (absent ones left out); nullopt when none was.
    std::optional<MaintenanceFactor> factors() const;
};

// K = L W / (h (L + W)). Throws std::invalid_argument (one line) unless all three are positive.
double roomIndex(double lengthM, double widthM, double mountingHeightM);
// The column of Table 4 whose room index is nearest K.
RoomSize roomSizeFor(double roomIndex, const Cie97Tables& tables);
// y at x on the polyline through (xs[i], ys[i]) (xs ascending, same sizes): exactly ys[i] at
// xs[i], linear between; nullopt outside [xs.front(), xs.back()] or for empty or unequal lists.
std::optional<double> interpolateLinearly(const std::vector<double>& xs, const std::vector<double>& ys, double x);

// The four factors for `choices`. Throws std::invalid_argument with a one-line reason for input
// out of range (hours or lengths not positive, an interval outside 0.5 to 3 years, an LED
// fraction outside (0, 1), a lamp the tables do not hold).
MaintenanceAssessment assessMaintenance(const MaintenanceChoices& choices,
                                        const Cie97Tables& tables = bundledCie97Tables());

}  // namespace lucerna
