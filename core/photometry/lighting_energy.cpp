#include "core/photometry/lighting_energy.h"

#include "core/number_format.h"

#include <array>
#include <stdexcept>

namespace lucerna {

namespace {

// EN 15193:2007 Table F.1 (the default operating hours the 2017 edition's quick method keeps).
constexpr std::array<BuildingTypeHours, 8> kTypes{{
    {BuildingType::Office, "office", "Offices", 2250, 250},
    {BuildingType::Education, "education", "Education buildings", 1800, 200},
    {BuildingType::Hospital, "hospital", "Hospitals", 3000, 2000},
    {BuildingType::Hotel, "hotel", "Hotels", 3000, 2000},
    {BuildingType::Restaurant, "restaurant", "Restaurants", 1250, 1250},
    {BuildingType::Sports, "sports", "Sports facilities", 2000, 2000},
    {BuildingType::Retail, "retail", "Wholesale and retail services", 3000, 1000},
    {BuildingType::Manufacturing, "manufacturing", "Manufacturing factories", 2500, 1500},
}};

// Without a charging time the emergency luminaires' chargers are taken to run all year (they
// trickle-charge whenever the mains is on): Lucerna's assumption, not a value of the standard.
constexpr double kDefaultEmergencyChargingHours = kHoursPerYear;

UsedFactor used(const std::optional<double>& given, double fallback) {
    return given ? UsedFactor{*given, true} : UsedFactor{fallback, false};
}

}  // namespace

std::span<const BuildingTypeHours> buildingTypes() { return kTypes; }

const BuildingTypeHours& buildingTypeHours(BuildingType type) {
    for (const BuildingTypeHours& t : kTypes)
        if (t.type == type) return t;
    return kTypes[0];
}

const BuildingTypeHours* findBuildingType(std::string_view key) {
    for (const BuildingTypeHours& t : kTypes)
        if (key == t.key) return &t;
    return nullptr;
}

std::string buildingTypeKeys() {
    std::string out;
    for (const BuildingTypeHours& t : kTypes) out += (out.empty() ? "" : ", ") + std::string(t.key);
    return out;
}

std::string energySettingsProblem(const EnergySettings& s) {
    const BuildingTypeHours& type = buildingTypeHours(s.buildingType);
    const double tD = s.daytimeHours.value_or(type.daytimeHours);
    const double tN = s.nightHours.value_or(type.nightHours);
    if (tD + tN <= kHoursPerYear) return {};
    const auto hours = [&](const char* key, const std::optional<double>& given, double value) {
        return std::string(key) + (given ? "" : std::string(" (") + type.key + "'s)") + " " + shortestNumber(value);
    };
    return hours("daytime_hours", s.daytimeHours, tD) + " + " + hours("night_time_hours", s.nightHours, tN) + " = " +
           shortestNumber(tD + tN) + " h, more than the 8760 h of a year";
}

LightingEnergy computeLightingEnergy(const EnergySettings& s, std::span<const double> circuitWatts, double areaM2) {
    if (const std::string problem = energySettingsProblem(s); !problem.empty()) throw std::invalid_argument(problem);
    const BuildingTypeHours& type = buildingTypeHours(s.buildingType);
    LightingEnergy e;
    e.buildingType = s.buildingType;
    e.daytimeHours = used(s.daytimeHours, type.daytimeHours);
    e.nightHours = used(s.nightHours, type.nightHours);
    e.constantIlluminanceFactor = used(s.constantIlluminanceFactor, 1);
    e.occupancyFactor = used(s.occupancyFactor, 1);
    e.daylightFactor = used(s.daylightFactor, 1);
    e.controlParasiticWatts = s.controlParasiticWatts;
    e.emergencyChargingWatts = s.emergencyChargingWatts;
    e.emergencyChargingHours = used(s.emergencyChargingHours, kDefaultEmergencyChargingHours);
    e.areaM2 = used(s.areaM2, areaM2);
    if (!(e.areaM2.value > 0))
        throw std::invalid_argument("the floor area is " + shortestNumber(e.areaM2.value) + " m², not positive");

    const double tD = e.daytimeHours.value, tN = e.nightHours.value;
    const double fc = e.constantIlluminanceFactor.value, fo = e.occupancyFactor.value, fd = e.daylightFactor.value;
    for (double pn : circuitWatts) {
        e.installedWatts += pn;
        e.lightingKWh += pn * fc * (tD * fo * fd + tN * fo) / 1000;
    }
    e.luminaires = int(circuitWatts.size());
    const double n = double(circuitWatts.size());
    e.controlParasiticKWh = e.controlParasiticWatts ? n * *e.controlParasiticWatts * (kHoursPerYear - tD - tN) / 1000
                                                    : kDefaultControlParasiticKWhPerM2 * e.areaM2.value;
    e.emergencyParasiticKWh = e.emergencyChargingWatts
                                  ? n * *e.emergencyChargingWatts * e.emergencyChargingHours.value / 1000
                                  : kDefaultEmergencyParasiticKWhPerM2 * e.areaM2.value;
    e.parasiticKWh = e.controlParasiticKWh + e.emergencyParasiticKWh;
    e.leni = (e.lightingKWh + e.parasiticKWh) / e.areaM2.value;
    return e;
}

}  // namespace lucerna
