#include "core/solar_position.h"

#include <cmath>
#include <cstdio>

namespace lucerna {

namespace {
bool isLeapYear(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }
int daysInMonth(int y, int m) {
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return m == 2 && isLeapYear(y) ? 29 : kDays[m - 1];
}
}  // namespace

std::optional<LocalTime> parseLocalTime(const std::string& text) {
    // Exactly "YYYY-MM-DDTHH:MM": 16 characters, digits where digits go.
    if (text.size() != 16 || text[4] != '-' || text[7] != '-' || text[10] != 'T' || text[13] != ':') return std::nullopt;
    for (size_t i : {0, 1, 2, 3, 5, 6, 8, 9, 11, 12, 14, 15})
        if (text[i] < '0' || text[i] > '9') return std::nullopt;
    auto digits = [&](size_t at, size_t n) {
        int v = 0;
        for (size_t i = 0; i < n; ++i) v = v * 10 + (text[at + i] - '0');
        return v;
    };
    LocalTime t;
    t.year = digits(0, 4);
    t.month = digits(5, 2);
    t.day = digits(8, 2);
    t.hour = digits(11, 2);
    t.minute = digits(14, 2);
    if (t.month < 1 || t.month > 12 || t.day < 1 || t.day > daysInMonth(t.year, t.month) || t.hour > 23 || t.minute > 59)
        return std::nullopt;
    return t;
}

std::string formatLocalTime(const LocalTime& t) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%04d-%02d-%02dT%02d:%02d", t.year, t.month, t.day, t.hour, t.minute);
    return buffer;
}

}  // namespace lucerna
