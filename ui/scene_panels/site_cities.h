#pragma once
// A few cities to place a scene's site at (the daylight panel's list): latitude and longitude in
// degrees (north and east positive) and the standard UTC offset in hours, without daylight saving
// (SPEC.md section 5's local time is the site's fixed offset).

#include <array>
#include <cmath>
#include <string_view>

namespace lucerna {

struct SiteCity {
    std::string_view name;
    double latitudeDeg, longitudeDeg, utcOffsetHours;
};

inline constexpr std::array<SiteCity, 16> kSiteCities{{
    {"London", 51.5074, -0.1278, 0},
    {"Paris", 48.8566, 2.3522, 1},
    {"Berlin", 52.5200, 13.4050, 1},
    {"Madrid", 40.4168, -3.7038, 1},
    {"Rome", 41.9028, 12.4964, 1},
    {"Lucerne", 47.0502, 8.3093, 1},
    {"Stockholm", 59.3293, 18.0686, 1},
    {"New York", 40.7128, -74.0060, -5},
    {"Chicago", 41.8781, -87.6298, -6},
    {"Los Angeles", 34.0522, -118.2437, -8},
    {"Sao Paulo", -23.5505, -46.6333, -3},
    {"Cape Town", -33.9249, 18.4241, 2},
    {"Mumbai", 19.0760, 72.8777, 5.5},
    {"Singapore", 1.3521, 103.8198, 8},
    {"Tokyo", 35.6762, 139.6503, 9},
    {"Sydney", -33.8688, 151.2093, 10},
}};

// The index of the city at that place, or -1: within 0.01 degrees of latitude and longitude
// (about a kilometre; sources round a city's centre differently: Paris is 48.8566, 2.3522 here and
// 48.857, 2.352 in the bundled office) and at the city's standard UTC offset (within a second: a
// site on another clock, summer time say, is not what choosing the city would make it).
inline int siteCityAt(double latitudeDeg, double longitudeDeg, double utcOffsetHours) {
    constexpr double kToleranceDeg = 0.01, kOffsetToleranceHours = 1.0 / 3600;
    for (size_t i = 0; i < kSiteCities.size(); ++i) {
        const SiteCity& c = kSiteCities[i];
        if (std::abs(c.latitudeDeg - latitudeDeg) <= kToleranceDeg && std::abs(c.longitudeDeg - longitudeDeg) <= kToleranceDeg &&
            std::abs(c.utcOffsetHours - utcOffsetHours) < kOffsetToleranceHours)
            return int(i);
    }
    return -1;
}

}  // namespace lucerna
