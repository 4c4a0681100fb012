#include "core/daylight/daylight_provision.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lucerna {

namespace {
// The value reached by at least `fraction` of the sorted values (the lower fractile).
double reachedBy(const std::vector<double>& ascending, double fraction) {
    if (ascending.empty()) return 0.0;
    const double k = (1.0 - fraction) * double(ascending.size() - 1);
    const size_t lo = size_t(std::floor(k)), hi = std::min(lo + 1, ascending.size() - 1);
    return ascending[lo] + (k - double(lo)) * (ascending[hi] - ascending[lo]);
}
}  // namespace

DaylightProvision checkDaylightProvision(const std::vector<double>& dfPercent, const std::vector<uint8_t>& insideGeometry,
                                         double medianDiffuseIlluminance) {
    DaylightProvision p;
    p.medianDiffuseIlluminance = medianDiffuseIlluminance;
    std::vector<double> values;
    for (size_t i = 0; i < dfPercent.size(); ++i)
        if (i >= insideGeometry.size() || !insideGeometry[i]) values.push_back(dfPercent[i]);
    std::sort(values.begin(), values.end());
    p.points = int(values.size());
    p.dfHalf = reachedBy(values, 0.5);
    p.df95 = reachedBy(values, 0.95);
    for (ProvisionLevel l : {ProvisionLevel{"minimum", 300, 100}, ProvisionLevel{"medium", 500, 300},
                             ProvisionLevel{"high", 750, 500}}) {
        l.targetDf = 100.0 * l.targetLux / medianDiffuseIlluminance;
        l.minimumTargetDf = 100.0 * l.minimumTargetLux / medianDiffuseIlluminance;
        l.targetMargin = p.dfHalf - l.targetDf;
        l.minimumMargin = p.df95 - l.minimumTargetDf;
        l.met = p.points > 0 && l.targetMargin >= 0 && l.minimumMargin >= 0;
        p.levels.push_back(l);
    }
    return p;
}

std::string describeProvision(const DaylightProvision& p) {
    std::string out;
    char line[400];
    for (const ProvisionLevel& l : p.levels) {
        std::snprintf(line, sizeof line,
                      "EN 17037 %s level: %s (DF on half the plane %.2f%% against %.2f%%, margin %+.2f; on 95%% %.2f%% "
                      "against %.2f%%, margin %+.2f)\n",
                      l.name, l.met ? "met" : "not met", p.dfHalf, l.targetDf, l.targetMargin, p.df95, l.minimumTargetDf,
                      l.minimumMargin);
        out += line;
    }
    return out;
}

}  // namespace lucerna
