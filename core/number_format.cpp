#include "core/number_format.h"

#include <charconv>
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

}  // namespace lucerna
