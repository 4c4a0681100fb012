#include "core/daylight/solar_position.h"

#include "core/daylight/spa_terms.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

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

// ---------------------------------------------------------------------------------------------
// NREL SPA (Reda and Andreas, NREL/TP-560-34302, revised 2008). "3.x" and "eq. n" are the
// report's sections and equations. Angles are in degrees unless a name says radians.
// ---------------------------------------------------------------------------------------------

namespace {

double degrees(double rad) { return rad * (180.0 / std::numbers::pi); }
double wrapDegrees(double deg) {  // into [0, 360)
    const double w = deg - 360.0 * std::floor(deg / 360.0);
    return w >= 360.0 ? 0.0 : w;
}

// 3.1.1, eq. 4: the Julian day of a UTC instant (UT1 when deltaUt1 is added), Gregorian calendar
// after 1582-10-15.
double julianDay(const LocalTime& t, double utcOffsetHours, double deltaUt1Seconds) {
    int year = t.year, month = t.month;
    const double day =
        t.day + (t.hour - utcOffsetHours + (t.minute + (t.second + deltaUt1Seconds) / 60.0) / 60.0) / 24.0;
    if (month < 3) {
        year -= 1;
        month += 12;
    }
    double jd = std::floor(365.25 * (year + 4716)) + std::floor(30.6001 * (month + 1)) + day - 1524.5;
    if (jd > 2299160.0) {
        const int centuries = year / 100;
        jd += 2 - centuries + centuries / 4;
    }
    return jd;
}

// TT - UT1 in seconds from Espenak and Meeus' polynomials (NASA's "Five Millennium Canon of
// Solar Eclipses", 2006) for 1900 to 2150, their long-term parabola elsewhere. SPA uses Delta T
// only to move the Earth along its orbit (about 1 degree a day), so even the parabola's error of
// tens of seconds far from 2000 shifts the sun by well under 0.001 degrees.
double estimatedDeltaTSeconds(int year, int month) {
    const double y = year + (month - 0.5) / 12.0;
    const double u = (y - 1820.0) / 100.0;
    if (y < 1900 || y >= 2150) return -20.0 + 32.0 * u * u;
    if (y < 1920) {
        const double t = y - 1900;
        return -2.79 + t * (1.494119 + t * (-0.0598939 + t * (0.0061966 + t * -0.000197)));
    }
    if (y < 1941) {
        const double t = y - 1920;
        return 21.20 + t * (0.84493 + t * (-0.076100 + t * 0.0020936));
    }
    if (y < 1961) {
        const double t = y - 1950;
        return 29.07 + 0.407 * t - t * t / 233.0 + t * t * t / 2547.0;
    }
    if (y < 1986) {
        const double t = y - 1975;
        return 45.45 + 1.067 * t - t * t / 260.0 - t * t * t / 718.0;
    }
    if (y < 2005) {
        const double t = y - 2000;
        return 63.86 + t * (0.3345 + t * (-0.060374 + t * (0.0017275 + t * (0.000651814 + t * 0.00002373599))));
    }
    if (y < 2050) {
        const double t = y - 2000;
        return 62.92 + 0.32217 * t + 0.005589 * t * t;
    }
    return -20.0 + 32.0 * u * u - 0.5628 * (2150.0 - y);
}

// 3.2, eq. 9 to 11: (X0 + X1 JME + X2 JME^2 + ...) / 1e8, each Xi the sum of its terms
// A cos(B + C JME); radians for L and B, AU for R.
template <size_t N>
double earthSeries(const std::array<std::span<const spa::EarthTerm>, N>& series, double jme) {
    double value = 0;
    for (size_t i = N; i-- > 0;) {
        double sum = 0;
        for (const spa::EarthTerm& term : series[i]) sum += term.a * std::cos(term.b + term.c * jme);
        value = value * jme + sum;
    }
    return value / 1e8;
}

struct Nutation {
    double longitude = 0;  // Delta psi
    double obliquity = 0;  // Delta epsilon
};

// 3.4: the nutation in longitude and obliquity from the mean elongation of the moon from the sun
// (X0), the mean anomalies of the sun (X1) and moon (X2), the moon's argument of latitude (X3) and
// the longitude of its ascending node (X4), eq. 15 to 23.
Nutation nutation(double jce) {
    auto cubic = [jce](double c0, double c1, double c2, double c3) { return c0 + jce * (c1 + jce * (c2 + jce * c3)); };
    const double x[5] = {
        cubic(297.85036, 445267.111480, -0.0019142, 1.0 / 189474.0),   // eq. 15
        cubic(357.52772, 35999.050340, -0.0001603, -1.0 / 300000.0),   // eq. 16
        cubic(134.96298, 477198.867398, 0.0086972, 1.0 / 56250.0),     // eq. 17
        cubic(93.27191, 483202.017538, -0.0036825, 1.0 / 327270.0),    // eq. 18
        cubic(125.04452, -1934.136261, 0.0020708, 1.0 / 450000.0)};    // eq. 19
    double psi = 0, epsilon = 0;
    for (const spa::NutationTerm& term : spa::kNutation) {
        double argument = 0;
        for (int j = 0; j < 5; ++j) argument += x[j] * term.y[j];
        psi += (term.a + term.b * jce) * std::sin(radians(argument));      // eq. 20
        epsilon += (term.c + term.d * jce) * std::cos(radians(argument));  // eq. 21
    }
    // eq. 22, 23: from 0.0001 arcseconds to degrees.
    return {psi / 36000000.0, epsilon / 36000000.0};
}

// 3.5, eq. 24: the mean obliquity of the ecliptic, arcseconds, in U = JME / 10.
double meanObliquityArcsec(double jme) {
    static constexpr double kCoefficients[] = {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                               -39.05,    7.12,     27.87, 5.79,    2.45};
    const double u = jme / 10.0;
    double value = 0;
    for (size_t i = std::size(kCoefficients); i-- > 0;) value = value * u + kCoefficients[i];
    return value;
}

// Where the sun stands seen from the Earth's centre at one instant (3.1 to 3.10), and the
// sidereal time that turns it into the observer's sky.
struct GeocentricSun {
    double rightAscension = 0;      // alpha, eq. 30
    double declination = 0;         // delta, eq. 31
    double siderealTime = 0;        // nu, apparent, at Greenwich, eq. 29
    double radiusAu = 1;            // R, the Earth-sun distance
};

GeocentricSun geocentricSun(double jd, double deltaTSeconds) {
    const double jde = jd + deltaTSeconds / 86400.0;  // eq. 5
    const double jc = (jd - 2451545.0) / 36525.0;     // eq. 6
    const double jce = (jde - 2451545.0) / 36525.0;   // eq. 7
    const double jme = jce / 10.0;                    // eq. 8

    // 3.2: the Earth seen from the sun (eq. 12: L in [0, 360)), 3.3: the sun seen from the Earth.
    const double heliocentricLongitude = wrapDegrees(degrees(earthSeries(spa::kLongitudeSeries, jme)));
    const double heliocentricLatitude = degrees(earthSeries(spa::kLatitudeSeries, jme));
    const double radius = earthSeries(spa::kRadiusSeries, jme);
    const double theta = wrapDegrees(heliocentricLongitude + 180.0);  // eq. 13
    const double beta = -heliocentricLatitude;                        // eq. 14

    const Nutation n = nutation(jce);
    const double epsilon = meanObliquityArcsec(jme) / 3600.0 + n.obliquity;  // 3.5, eq. 25
    const double aberration = -20.4898 / (3600.0 * radius);                 // 3.6, eq. 26
    const double lambda = theta + n.longitude + aberration;                 // 3.7, eq. 27

    // 3.8: the mean sidereal time at Greenwich (eq. 28), made apparent by the nutation (eq. 29).
    const double nu0 = wrapDegrees(280.46061837 + 360.98564736629 * (jd - 2451545.0) + jc * jc * (0.000387933 - jc / 38710000.0));
    const double nu = nu0 + n.longitude * std::cos(radians(epsilon));

    // 3.9, 3.10: ecliptic to equatorial coordinates.
    const double lambdaRad = radians(lambda), epsilonRad = radians(epsilon), betaRad = radians(beta);
    GeocentricSun sun;
    sun.rightAscension = wrapDegrees(degrees(std::atan2(
        std::sin(lambdaRad) * std::cos(epsilonRad) - std::tan(betaRad) * std::sin(epsilonRad), std::cos(lambdaRad))));
    sun.declination = degrees(std::asin(std::sin(betaRad) * std::cos(epsilonRad) +
                                        std::cos(betaRad) * std::sin(epsilonRad) * std::sin(lambdaRad)));
    sun.siderealTime = nu;
    sun.radiusAu = radius;
    return sun;
}

// The sun's topocentric declination and hour angle: 3.12 and 3.13, the parallax of an observer
// on the Earth's surface (the reference ellipsoid, flattening 1 - 0.99664719) rather than at its
// centre.
struct Topocentric {
    double declination = 0;  // delta', eq. 39
    double hourAngle = 0;    // H', eq. 40
};

Topocentric topocentric(const GeocentricSun& sun, double hourAngle, double latitudeDeg, double elevationM) {
    constexpr double kEquatorialRadiusM = 6378140.0;
    const double xi = radians(8.794 / (3600.0 * sun.radiusAu));  // eq. 33, equatorial horizontal parallax
    const double phi = radians(latitudeDeg);
    const double u = std::atan(0.99664719 * std::tan(phi));  // eq. 34
    const double x = std::cos(u) + elevationM / kEquatorialRadiusM * std::cos(phi);             // eq. 35
    const double y = 0.99664719 * std::sin(u) + elevationM / kEquatorialRadiusM * std::sin(phi);  // eq. 36
    const double h = radians(hourAngle), delta = radians(sun.declination);
    const double denominator = std::cos(delta) - x * std::sin(xi) * std::cos(h);
    const double deltaAlpha = std::atan2(-x * std::sin(xi) * std::sin(h), denominator);  // eq. 37
    Topocentric t;
    t.declination = degrees(std::atan2((std::sin(delta) - y * std::sin(xi)) * std::cos(deltaAlpha), denominator));  // eq. 39
    t.hourAngle = hourAngle - degrees(deltaAlpha);  // eq. 40
    return t;
}

// 3.14, eq. 42: the refraction lift of the apparent elevation, degrees. SPA applies it only while
// the sun's upper limb can still be lifted into view: true elevation at least -(0.26667 + 0.5667)
// degrees (the sun's radius and the refraction at the horizon).
double refraction(double trueElevation, double pressureMbar, double temperatureC) {
    constexpr double kSunRadius = 0.26667, kHorizonRefraction = 0.5667;
    if (trueElevation < -(kSunRadius + kHorizonRefraction)) return 0.0;
    return (pressureMbar / 1010.0) * (283.0 / (273.0 + temperatureC)) * 1.02 /
           (60.0 * std::tan(radians(trueElevation + 10.3 / (trueElevation + 5.11))));
}

}  // namespace

SolarPosition solarPosition(const SolarPositionInput& in) {
    const double jd = julianDay(in.time, in.utcOffsetHours, in.deltaUt1Seconds);
    const double deltaT = in.deltaTSeconds.value_or(estimatedDeltaTSeconds(in.time.year, in.time.month));
    const GeocentricSun sun = geocentricSun(jd, deltaT);

    // 3.11, eq. 32: the observer's local hour angle.
    const double hourAngle = wrapDegrees(sun.siderealTime + in.longitudeDeg - sun.rightAscension);
    const Topocentric t = topocentric(sun, hourAngle, in.latitudeDeg, in.elevationM);

    // 3.14: elevation without (eq. 41) and with (eq. 43) refraction; zenith (eq. 44).
    const double phi = radians(in.latitudeDeg), delta = radians(t.declination), h = radians(t.hourAngle);
    const double e0 = degrees(std::asin(std::clamp(
        std::sin(phi) * std::sin(delta) + std::cos(phi) * std::cos(delta) * std::cos(h), -1.0, 1.0)));
    const double e = e0 + refraction(e0, in.pressureMbar, in.temperatureC);

    // 3.15: the astronomers' azimuth, from south westward (eq. 45), turned to navigators' (from
    // north eastward, eq. 46).
    const double gamma = degrees(std::atan2(std::sin(h), std::cos(h) * std::sin(phi) - std::tan(delta) * std::cos(phi)));
    SolarPosition p;
    p.zenithDeg = 90.0 - e;
    p.azimuthDeg = wrapDegrees(gamma + 180.0);
    return p;
}

V3d directionTowardSun(const SolarPosition& position, const V3d& north) {
    const V3d up(0, 1, 0);
    V3d n(north.x, 0, north.z);
    n = n.length() > 0 ? n.normalized() : V3d(0, 0, -1);
    const V3d east = n.cross(up);
    const double elevation = radians(90.0 - position.zenithDeg), azimuth = radians(position.azimuthDeg);
    return (n * std::cos(azimuth) + east * std::sin(azimuth)) * std::cos(elevation) + up * std::sin(elevation);
}

}  // namespace lucerna
