#pragma once
// Climate-based daylight metrics from an hourly illuminance matrix (SPEC.md section 6): per point
// DA300, UDI and the ASE hour count, and over the plane sDA300/50%, ASE1000,250h, the UDI means
// and EN 17037's illuminance method.
//  - DA300, sDA300/50% and ASE1000,250h: IES LM-83-12, "Approved Method: IES Spatial Daylight
//    Autonomy (sDA) and Annual Sunlight Exposure (ASE)". sDA here has no blind schedule: LM-83
//    closes blinds in hours where more than 2% of the points see over 1000 lx of direct sun; that
//    schedule is not modelled, so the figure is that of the open glazing all year.
//  - UDI: Nabil and Mardaljevic, "Useful daylight illuminance: a new paradigm for assessing
//    daylight in buildings", Lighting Research and Technology 37 (2005), with the 3000 lx upper
//    bound of Mardaljevic, Andersen, Roy and Christoffersen, "Daylighting metrics: is there a
//    relation between useful daylight illuminance and daylight glare probability?" (BSO 2012).
//  - EN 17037:2018 annex A, the illuminance method: over the half of the year's hours with the
//    most diffuse daylight, E_T on half the plane and E_TM on 95% of it, each for at least half of
//    those hours.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace lucerna {

// One row of the weather year as the metrics need it.
struct AnnualHour {
    int month = 1, day = 1, hour = 1;   // EPW: the hour ending at `hour` (1..24), local standard time
    double diffuseIlluminanceLux = 0;   // Evd of SPEC.md section 6's Perez model (ranks EN 17037's daylight hours)
};

// Occupied hours: instants (hour - 0.5) in [fromHour, toHour) local standard time (SPEC: default 8-18).
struct Occupancy {
    double fromHour = 8, toHour = 18;
    bool contains(const AnnualHour& h) const;
};

struct PointAnnualMetrics {
    double da300 = 0;                 // fraction of occupied hours with E >= 300 lx
    double udiFellShort = 0, udiUseful = 0, udiExceeded = 0;  // E < 100, 100 <= E <= 3000, E > 3000
    int aseHours = 0;                 // occupied hours with direct sun alone > 1000 lx
    double meanLux = 0;               // over the occupied hours
};

struct En17037Level {
    std::string name;                 // "minimum", "medium", "high"
    double targetLux = 0, minimumTargetLux = 0;  // E_T, E_TM: 300/100, 500/300, 750/500
    double fractionTarget = 0;        // fraction of daylight hours with E >= E_T at >= 50% of the points
    double fractionMinimum = 0;       // fraction of daylight hours with E >= E_TM at >= 95% of the points
    bool met = false;                 // both fractions >= 0.5
};

struct AnnualMetrics {
    std::vector<PointAnnualMetrics> points;
    int occupiedHours = 0, daylightHours = 0;   // daylightHours: EN 17037's half of the rows
    int countedPoints = 0;            // those the plane's figures are over
    double sda300 = 0;                // percent of points with DA300 >= 0.5
    double ase = 0;                   // percent of points with aseHours > 250
    double udiFellShort = 0, udiUseful = 0, udiExceeded = 0;  // means over the points, fractions
    std::array<En17037Level, 3> en17037;
};

// lux and directSunLux are hours x points, row-major (lux[h * points + p]); `counted` (may be
// empty: all) marks the points that count toward the plane's figures (points inside geometry are
// left out of sDA, ASE, UDI means and EN 17037 but still get their PointAnnualMetrics).
// directSunLux may also be empty: no direct sun, ASE 0. With no occupied hours every fraction is
// 0; with no counted points the plane's figures are 0 and no EN 17037 level is met. Throws
// std::invalid_argument when a span's size does not fit hours x points.
AnnualMetrics computeAnnualMetrics(std::span<const AnnualHour> hours, size_t points, std::span<const float> lux,
                                   std::span<const float> directSunLux, const Occupancy& occupancy,
                                   std::span<const uint8_t> counted = {});

// EN 17037's daylight hours: the indices of the half of the rows (rounded down) with the highest
// Evd, earlier hours first on ties; returned in row order.
std::vector<size_t> en17037DaylightHours(std::span<const AnnualHour> hours);

}  // namespace lucerna
