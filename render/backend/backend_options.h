#pragma once
// Reading backend options ("name=value" from --option or a bench entry) into settings, one way for
// every backend: an option that is absent leaves the default; one that is not a number in range
// is std::invalid_argument with a one-line message (the command line's exit status 2).

#include "render/backend/backend.h"
#include "render/trace/lights/light_sampler.h"

#include <limits>

namespace lucerna {

// options[key] as an integer in [lo, hi] into value, when present.
void readOption(const RenderSettings& settings, const char* key, int& value, int lo,
                int hi = std::numeric_limits<int>::max());
// options[key] as a number in [lo, hi] into value, when present.
void readOption(const RenderSettings& settings, const char* key, float& value, double lo, double hi);

// options["light_sampler"]: power or tree; kDefaultLightSelection when absent.
LightSelection lightSelectionOption(const RenderSettings& settings);
// Option daylight_portals=on|off: whether sky and sun particles travel through the windows
// (daylight_portals.h) or from the disc around the scene; byDefault where not given.
bool daylightPortalsOption(const RenderSettings& settings, bool byDefault);

}  // namespace lucerna
