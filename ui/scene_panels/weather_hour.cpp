#include "ui/scene_panels/weather_hour.h"

#include "core/daylight/daylight.h"
#include "core/daylight/solar_position.h"
#include "render/annual/annual_calculation.h"
#include "ui/commands/daylight_commands.h"

namespace lucerna {

std::optional<DaylightEdit> weatherHourDaylight(const Scene& scene, const WeatherFile& weather, const std::string& localTime,
                                                const std::string& newSunName) {
    const auto t = parseLocalTime(localTime);
    if (!t) return std::nullopt;
    const auto row = weatherRow(weather, t->month, t->day, t->hour + 1);
    if (!row) return std::nullopt;
    const HourDaylight hour = daylightOfHour(scene, weather, *row);
    DaylightEdit e;
    e.site = hour.site;
    e.sky = hour.sky;
    e.sunIndex = sunIndex(scene);
    e.sun = e.sunIndex >= 0 ? scene.lights[size_t(e.sunIndex)] : hour.sun;
    if (e.sunIndex < 0) e.sun.name = newSunName;
    SunSpec keys = e.sun.sun.value_or(SunSpec());
    keys.time = localTime;  // where the clock says, within the hour
    keys.illuminanceGiven = false;
    e.sun.sun = keys;
    return e;
}

DaylightEdit leavePerez(const Scene& scene, SkyModelType model) {
    const Daylight d = resolveDaylight(scene);
    DaylightEdit e;
    e.site = scene.site.value_or(Site());
    e.sunIndex = sunIndex(scene);
    if (e.sunIndex >= 0) {
        e.sun = scene.lights[size_t(e.sunIndex)];
        SunSpec keys = e.sun.sun.value_or(SunSpec());
        keys.illuminanceLux = d.sun ? d.sun->illuminanceLux : 0;
        keys.illuminanceGiven = true;
        e.sun.sun = keys;
    }
    e.sky.model = model;
    e.sky.cieType = model == SkyModelType::CieGeneral ? 12 : 0;
    e.sky.horizontalIlluminance = d.sky ? d.sky->horizontalIlluminance : 0.0;
    if (scene.sky) e.sky.groundReflectance = scene.sky->groundReflectance, e.sky.groundReflectanceGiven = scene.sky->groundReflectanceGiven;
    return e;
}

}  // namespace lucerna
