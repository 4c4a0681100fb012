#pragma once
// Where the sun stands: NREL's Solar Position Algorithm (Reda and Andreas, "Solar position
// algorithm for solar radiation applications", NREL/TP-560-34302, 2008 revision), which is good to
// 0.0003 degrees from the year -2000 to 6000, and the local time of a scene's sun (SPEC.md
// section 5: "YYYY-MM-DDTHH:MM" at the site's UTC offset).

#include "core/math.h"

#include <optional>
#include <string>

namespace lucerna {

struct LocalTime {
    int year = 2000, month = 1, day = 1;  // Gregorian calendar
    int hour = 12, minute = 0;
    double second = 0;                    // the API takes seconds; the scene file does not
    bool operator==(const LocalTime&) const = default;
};

// "YYYY-MM-DDTHH:MM" with a real calendar date (leap years included), hours 00..23, minutes
// 00..59; nullopt for anything else.
std::optional<LocalTime> parseLocalTime(const std::string& text);
// The inverse: "YYYY-MM-DDTHH:MM" (seconds dropped).
std::string formatLocalTime(const LocalTime& t);

struct SolarPositionInput {
    LocalTime time;
    double utcOffsetHours = 0;      // local time = UTC + offset
    double latitudeDeg = 0;         // north positive
    double longitudeDeg = 0;        // east positive
    double elevationM = 0;          // observer's height above sea level
    double pressureMbar = 1010;     // annual mean local pressure, for refraction
    double temperatureC = 10;       // annual mean local temperature, for refraction
    // TT - UT1, seconds; nullopt: estimated for the year (Espenak and Meeus' polynomials).
    std::optional<double> deltaTSeconds;
    double deltaUt1Seconds = 0;     // UT1 - UTC, seconds
};

struct SolarPosition {
    double zenithDeg = 0;   // topocentric, refraction included (the apparent position)
    double azimuthDeg = 0;  // from north, eastward, in [0, 360)
};

// SPA's topocentric zenith (refraction-corrected) and azimuth.
SolarPosition solarPosition(const SolarPositionInput& input);

// The unit world direction toward a sun at this position, for a scene whose up is +y and whose
// geographic north is the horizontal direction `north` (east = north x up).
V3d directionTowardSun(const SolarPosition& position, const V3d& north);

}  // namespace lucerna
