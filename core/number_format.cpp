#include "core/number_format.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace lucerna {

std::string shortestNumber(double x) {
    char buf[40];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
}

std::string formatNumber(double v, int significantDigits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", significantDigits, v);
    return buf;
}

std::string fixedNumber(double v, int decimals) {
    char buf[352];  // %f of DBL_MAX has 309 digits
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    if (s.size() > 1 && s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
    return s;
}

std::string formatDuration(double seconds) {
    char buf[48];
    // Rounded once, so that 59.96 s, which reads "60.0 s" to a tenth, is "1 min 00 s".
    if (std::round(seconds * 10) >= 600) {
        const long long whole = std::llround(seconds);
        std::snprintf(buf, sizeof buf, "%lld min %02lld s", whole / 60, whole % 60);
    } else {
        std::snprintf(buf, sizeof buf, "%.1f s", seconds);
    }
    return buf;
}

}  // namespace lucerna
