#pragma once
// The EnergyPlus EPW weather file that annual daylight runs on (SPEC.md section 6): the LOCATION
// line and one row per hour of the year, read strictly, so that a damaged or sub-hourly file is a
// one-line error naming its line rather than a year of wrong skies.

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

namespace lucerna {

// One row of the file: the hour ending at `hour` (1..24) local standard time on month/day.
struct WeatherHour {
    int month = 1, day = 1, hour = 1;
    double dewPointC = 11;                   // field 8; 99.9 (missing) reads as 11
    double directNormalIrradiance = 0;       // field 15, W/m^2 (Wh/m^2 over the hour); 9999 reads as 0
    double diffuseHorizontalIrradiance = 0;  // field 16, W/m^2; 9999 reads as 0
    bool missing = false;                    // one of the three was missing
};

struct WeatherFile {
    std::string city, region, country, source, wmo;                               // LOCATION fields 2..6
    double latitudeDeg = 0, longitudeDeg = 0, timeZoneHours = 0, elevationM = 0;  // fields 7..10
    std::vector<WeatherHour> hours;  // 8760 or 8784, in calendar order
    int hoursWithMissingValues = 0;
    // The year instants fall in (SPEC.md: 2021 for 8760 rows, 2020 for 8784).
    int year() const { return hours.size() == 8784 ? 2020 : 2021; }
    // "city, region, country (source, WMO wmo), latitude N, longitude E, UTC+tz" style one-liner for the CLI.
    std::string describe() const;
};

// A one-line error naming the file and line: "FILE:LINE: what is wrong" (LINE counted from 1).
class WeatherFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads an EPW file strictly as SPEC.md section 6 says; throws WeatherFileError.
WeatherFile readWeatherFile(const std::string& path);

// The same from a stream; `name` is what errors call the file.
WeatherFile parseWeatherFile(std::istream& in, const std::string& name);

}  // namespace lucerna
