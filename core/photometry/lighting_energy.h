#pragma once
// The annual energy a lighting installation uses, by EN 15193-1 (README, "Energy (LENI; an
// addition)"): the lighting energy numeric indicator LENI = (W_L + W_P) / A in kWh/(m²·a), with
//   W_L = sum over luminaires of Pn Fc (tD Fo FD + tN Fo) / 1000             (kWh/a)
//   W_P = sum over luminaires of (Ppc (8760 - tD - tN) + Pem tem) / 1000     (kWh/a)
// Pn the luminaire's circuit power (W); Fc the constant illuminance factor, Fo the occupancy
// dependency factor, FD the daylight dependency factor; tD, tN the daytime and night-time
// operating hours a year; Ppc the parasitic (control) power and Pem the emergency charging power
// of each luminaire (W), tem the emergency charging hours a year; A the floor area (m²).
// The hours default to the building type's (EN 15193:2007 Table F.1), the three factors to 1 (no
// such control), and a parasitic power not given to the quick method's energy per area: 5
// kWh/(m²·a) for controls, 1 kWh/(m²·a) for emergency lighting. Pure: no scene, no Qt.

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace lucerna {

inline constexpr double kHoursPerYear = 8760;  // the standard year, h
// The quick method's parasitic energy per square metre, kWh/(m²·a), used where the design gives
// no parasitic power.
inline constexpr double kDefaultControlParasiticKWhPerM2 = 5;
inline constexpr double kDefaultEmergencyParasiticKWhPerM2 = 1;

enum class BuildingType { Office, Education, Hospital, Hotel, Restaurant, Sports, Retail, Manufacturing };

// A building type of EN 15193's table of default operating hours.
struct BuildingTypeHours {
    BuildingType type;
    const char* key;    // as the scene file writes it: "office", ...
    const char* name;   // as the standard names it: "Offices", ...
    double daytimeHours;  // tD, h/a
    double nightHours;    // tN, h/a
};

// The eight types, in the table's order.
std::span<const BuildingTypeHours> buildingTypes();
const BuildingTypeHours& buildingTypeHours(BuildingType type);
// The type whose key is `key`, or null.
const BuildingTypeHours* findBuildingType(std::string_view key);
// "office, education, ..." for messages.
std::string buildingTypeKeys();

// What a design says about its energy (the scene's "energy" key): the building type, and each
// factor where the design gives it (absent: the default above).
struct EnergySettings {
    BuildingType buildingType = BuildingType::Office;
    std::optional<double> daytimeHours, nightHours;            // tD, tN, h/a, each in [0, 8760]
    std::optional<double> constantIlluminanceFactor;           // Fc, in [0, 1]
    std::optional<double> occupancyFactor;                     // Fo, in [0, 1]
    std::optional<double> daylightFactor;                      // FD, in [0, 1]
    std::optional<double> controlParasiticWatts;               // Ppc per luminaire, W, at least 0
    std::optional<double> emergencyChargingWatts;              // Pem per luminaire, W, at least 0
    std::optional<double> emergencyChargingHours;              // tem, h/a, in [0, 8760]
    std::optional<double> areaM2;                              // A, m², positive (absent: the scene's)

    bool operator==(const EnergySettings&) const = default;
};

// Why `settings` cannot be used, in one line naming the keys ("daytime_hours + night_time_hours =
// 8600 + 250 h, more than the 8760 h of a year"), or empty when it can. Each value's own range is
// the parser's; this checks what spans values.
std::string energySettingsProblem(const EnergySettings& settings);

// One factor as used, and whether the design gave it (else it is the default).
struct UsedFactor {
    double value = 0;
    bool given = false;
};

// W_L, W_P, LENI and every factor behind them, so that a report can state them all.
struct LightingEnergy {
    BuildingType buildingType = BuildingType::Office;
    UsedFactor daytimeHours, nightHours, constantIlluminanceFactor, occupancyFactor, daylightFactor;
    std::optional<double> controlParasiticWatts, emergencyChargingWatts;  // absent: the per-area default
    UsedFactor emergencyChargingHours;  // used only with emergencyChargingWatts
    UsedFactor areaM2;
    int luminaires = 0;              // counted
    double installedWatts = 0;       // sum of Pn, W
    double lightingKWh = 0;          // W_L, kWh/a
    double controlParasiticKWh = 0;  // the Ppc part of W_P, kWh/a
    double emergencyParasiticKWh = 0;// the Pem part of W_P, kWh/a
    double parasiticKWh = 0;         // W_P, kWh/a
    double leni = 0;                 // kWh/(m²·a)
};

// The energy of luminaires of circuit powers `circuitWatts` (W each) on `areaM2` (m², used unless
// settings.areaM2 is given). `settings` must have no problem (energySettingsProblem), the area
// must be positive; throws std::invalid_argument otherwise.
LightingEnergy computeLightingEnergy(const EnergySettings& settings, std::span<const double> circuitWatts,
                                     double areaM2);

}  // namespace lucerna
