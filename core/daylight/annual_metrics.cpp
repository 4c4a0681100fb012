#include "core/daylight/annual_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace lucerna {

namespace {

// EN 17037:2018's levels for vertical and inclined openings (annex A).
struct LevelTargets {
    const char* name;
    float targetLux, minimumTargetLux;
};
constexpr std::array<LevelTargets, 3> kEn17037Levels{{{"minimum", 300, 100}, {"medium", 500, 300}, {"high", 750, 500}}};

constexpr float kDaThresholdLux = 300;        // LM-83's sDA300/50%
constexpr float kUdiLowerLux = 100, kUdiUpperLux = 3000;
constexpr float kAseThresholdLux = 1000;      // LM-83's ASE1000,250h
constexpr int kAseHourLimit = 250;

// "At least half" and "at least 95%" of a count (points of the plane, hours), in integers so that
// exactly 50% or 95% counts, whatever the rounding of a division.
bool reachesHalf(int reached, int of) { return 2 * int64_t(reached) >= int64_t(of); }
bool reaches95Percent(int reached, int of) { return 100 * int64_t(reached) >= 95 * int64_t(of); }

}  // namespace

bool Occupancy::contains(const AnnualHour& h) const {
    const double instant = h.hour - 0.5;
    return instant >= fromHour && instant < toHour;
}

std::vector<size_t> en17037DaylightHours(std::span<const AnnualHour> hours) {
    // A NaN would break the strict ordering nth_element needs; such an hour has no daylight to rank.
    auto evd = [&](size_t i) {
        const double v = hours[i].diffuseIlluminanceLux;
        return std::isnan(v) ? -std::numeric_limits<double>::infinity() : v;
    };
    // The row index breaks ties, so the order is total and the chosen half is unique.
    auto ranksBefore = [&](size_t a, size_t b) {
        const double ea = evd(a), eb = evd(b);
        return ea > eb || (ea == eb && a < b);
    };
    std::vector<size_t> rows(hours.size());
    std::iota(rows.begin(), rows.end(), size_t(0));
    const size_t half = hours.size() / 2;
    std::nth_element(rows.begin(), rows.begin() + ptrdiff_t(half), rows.end(), ranksBefore);
    rows.resize(half);
    std::sort(rows.begin(), rows.end());
    return rows;
}

AnnualMetrics computeAnnualMetrics(std::span<const AnnualHour> hours, size_t points, std::span<const float> lux,
                                   std::span<const float> directSunLux, const Occupancy& occupancy,
                                   std::span<const uint8_t> counted) {
    const size_t rows = hours.size();
    if (lux.size() != rows * points)
        throw std::invalid_argument("annual metrics: the illuminance matrix needs one value per hour and point");
    if (!directSunLux.empty() && directSunLux.size() != rows * points)
        throw std::invalid_argument("annual metrics: the direct-sun matrix needs one value per hour and point");
    if (!counted.empty() && counted.size() != points)
        throw std::invalid_argument("annual metrics: `counted` needs one flag per point");

    std::vector<uint8_t> countsOnPlane(points, 1);
    for (size_t p = 0; p < counted.size(); ++p) countsOnPlane[p] = counted[p] ? 1 : 0;
    const int planePoints = int(std::count(countsOnPlane.begin(), countsOnPlane.end(), uint8_t(1)));

    std::vector<uint8_t> isDaylightHour(rows, 0);
    const std::vector<size_t> daylightRows = en17037DaylightHours(hours);
    for (size_t h : daylightRows) isDaylightHour[h] = 1;

    // One pass over the matrix, row by row, so that each row's values are read once, in order,
    // into per-point tallies laid out as separate arrays the inner loops can vectorise.
    std::vector<int> reachedDa(points, 0), fellShort(points, 0), exceeded(points, 0), aseHours(points, 0);
    std::vector<double> luxSum(points, 0.0);
    std::array<int, 3> hoursAtTarget{}, hoursAtMinimum{};
    int occupiedHours = 0;
    for (size_t h = 0; h < rows; ++h) {
        const float* e = lux.data() + h * points;
        if (occupancy.contains(hours[h])) {
            ++occupiedHours;
            for (size_t p = 0; p < points; ++p) {
                const float v = e[p];
                reachedDa[p] += v >= kDaThresholdLux;
                fellShort[p] += v < kUdiLowerLux;
                exceeded[p] += v > kUdiUpperLux;
                luxSum[p] += v;
            }
            if (!directSunLux.empty()) {
                const float* sun = directSunLux.data() + h * points;
                for (size_t p = 0; p < points; ++p) aseHours[p] += sun[p] > kAseThresholdLux;
            }
        }
        if (isDaylightHour[h] && planePoints > 0) {
            // Each hour is judged over the plane first (SPEC.md section 6), then the hours counted.
            std::array<int, 3> atTarget{}, atMinimum{};
            for (size_t p = 0; p < points; ++p) {
                const float v = e[p];
                const int c = countsOnPlane[p];
                for (size_t l = 0; l < kEn17037Levels.size(); ++l) {
                    atTarget[l] += c & int(v >= kEn17037Levels[l].targetLux);
                    atMinimum[l] += c & int(v >= kEn17037Levels[l].minimumTargetLux);
                }
            }
            for (size_t l = 0; l < kEn17037Levels.size(); ++l) {
                hoursAtTarget[l] += reachesHalf(atTarget[l], planePoints);
                hoursAtMinimum[l] += reaches95Percent(atMinimum[l], planePoints);
            }
        }
    }

    AnnualMetrics m;
    m.occupiedHours = occupiedHours;
    m.daylightHours = int(daylightRows.size());
    m.countedPoints = planePoints;
    m.points.resize(points);
    int sdaPoints = 0, asePoints = 0;
    for (size_t p = 0; p < points; ++p) {
        PointAnnualMetrics& pm = m.points[p];
        pm.aseHours = aseHours[p];
        if (occupiedHours > 0) {
            const double n = occupiedHours;
            pm.da300 = reachedDa[p] / n;
            pm.udiFellShort = fellShort[p] / n;
            pm.udiExceeded = exceeded[p] / n;
            pm.udiUseful = (occupiedHours - fellShort[p] - exceeded[p]) / n;
            pm.meanLux = luxSum[p] / n;
        }
        if (!countsOnPlane[p]) continue;
        // DA300 >= 0.5 in integers, for the same reason as the plane's shares above.
        sdaPoints += occupiedHours > 0 && reachesHalf(reachedDa[p], occupiedHours);
        asePoints += pm.aseHours > kAseHourLimit;
        m.udiFellShort += pm.udiFellShort;
        m.udiUseful += pm.udiUseful;
        m.udiExceeded += pm.udiExceeded;
    }
    if (planePoints > 0) {
        m.sda300 = 100.0 * sdaPoints / planePoints;
        m.ase = 100.0 * asePoints / planePoints;
        m.udiFellShort /= planePoints;
        m.udiUseful /= planePoints;
        m.udiExceeded /= planePoints;
    }

    for (size_t l = 0; l < kEn17037Levels.size(); ++l) {
        En17037Level& level = m.en17037[l];
        level.name = kEn17037Levels[l].name;
        level.targetLux = kEn17037Levels[l].targetLux;
        level.minimumTargetLux = kEn17037Levels[l].minimumTargetLux;
        if (m.daylightHours == 0 || planePoints == 0) continue;
        level.fractionTarget = double(hoursAtTarget[l]) / m.daylightHours;
        level.fractionMinimum = double(hoursAtMinimum[l]) / m.daylightHours;
        level.met = reachesHalf(hoursAtTarget[l], m.daylightHours) && reachesHalf(hoursAtMinimum[l], m.daylightHours);
    }
    return m;
}

}  // namespace lucerna
