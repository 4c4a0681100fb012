#pragma once
// The daylight dock's Perez sky: a weather file's hour as the scene's daylight (SPEC.md section
// 6: one hour is a scene). The hour is the one the dock's clock falls in; the sun stands where
// the clock says, the sky takes the hour's irradiances, the site the weather file's place (the
// scene's north stays). Leaving the Perez sky for another model keeps the light the hour gave:
// the sun gets the model's direct normal illuminance, the sky its horizontal illuminance.

#include "core/daylight/epw_file.h"
#include "core/scene/scene.h"

#include <optional>
#include <string>

namespace lucerna {

struct DaylightEdit {
    Site site;
    Light sun;          // the scene's sun edited, or a new one
    int sunIndex = -1;  // in Scene::lights; -1: the sun is added
    Sky sky;
};

// The scene's daylight as the weather file's hour at `localTime` ("YYYY-MM-DDTHH:MM", the hour
// ending at the next full hour); nothing when the file has no such row (29 February in a
// 365-day file).
std::optional<DaylightEdit> weatherHourDaylight(const Scene& scene, const WeatherFile& weather, const std::string& localTime,
                                                const std::string& newSunName);

// The scene's perez daylight as the sky `model` (uniform, cie_overcast, cie_general type 12)
// with the same horizontal illuminance, and the sun with the hour's direct normal illuminance.
DaylightEdit leavePerez(const Scene& scene, SkyModelType model);

}  // namespace lucerna
