#pragma once
// EN 17037:2018's daylight provision by the daylight-factor method (for vertical and inclined
// openings): a level is met when the daylight factor reaches D_T = 100 E_T / E_v,d,med over half
// of the reference plane and D_TM = 100 E_TM / E_v,d,med over 95% of it, E_v,d,med the site's
// median external diffuse illuminance. Levels (E_T / E_TM, lx): minimum 300 / 100, medium
// 500 / 300, high 750 / 500. For 15,000 lx the minimum level asks 2% and 0.7%.

#include <cstdint>
#include <string>
#include <vector>

namespace lucerna {

// The value EN 17037 assumes where a site gives none (about that of central Europe), lx.
inline constexpr double kDefaultMedianDiffuseIlluminance = 15000.0;

struct ProvisionLevel {
    const char* name;            // "minimum", "medium", "high"
    double targetLux, minimumTargetLux;
    double targetDf = 0, minimumTargetDf = 0;  // %, for the site
    double targetMargin = 0, minimumMargin = 0;// percentage points: the plane's DF minus the target
    bool met = false;
};

struct DaylightProvision {
    double medianDiffuseIlluminance = kDefaultMedianDiffuseIlluminance;  // lx
    double dfHalf = 0;      // %: the DF that half of the plane's points reach (the median)
    double df95 = 0;        // %: the DF that 95% of them reach
    int points = 0;         // points counted (those inside geometry left out)
    std::vector<ProvisionLevel> levels;  // minimum, medium, high
};

// The check on daylight factors (%) at the points of a plane; points marked inside geometry
// (insideGeometry[i] != 0, if given) are left out.
DaylightProvision checkDaylightProvision(const std::vector<double>& dfPercent, const std::vector<uint8_t>& insideGeometry,
                                         double medianDiffuseIlluminance);

// "EN 17037 minimum level: met (DF 2.41% on half the plane against 2.00%, margin +0.41; ...)".
std::string describeProvision(const DaylightProvision& p);

}  // namespace lucerna
