#include "render/backend/backend_options.h"

#include "core/number_format.h"

#include <charconv>
#include <stdexcept>

namespace lucerna {

namespace {
template <class T>
bool parseWhole(const std::string& text, T& out) {
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && ptr == text.data() + text.size();
}

[[noreturn]] void badOption(const char* key, const std::string& what, const std::string& given) {
    throw std::invalid_argument(std::string("option ") + key + " must be " + what + ", got '" + given + "'");
}
}  // namespace

void readOption(const RenderSettings& settings, const char* key, int& value, int lo, int hi) {
    const auto it = settings.options.find(key);
    if (it == settings.options.end()) return;
    int v = 0;
    if (!parseWhole(it->second, v) || v < lo || v > hi)
        badOption(key,
                  hi == std::numeric_limits<int>::max()
                      ? "an integer >= " + std::to_string(lo)
                      : "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
                  it->second);
    value = v;
}

void readOption(const RenderSettings& settings, const char* key, float& value, double lo, double hi) {
    const auto it = settings.options.find(key);
    if (it == settings.options.end()) return;
    double v = 0;
    if (!parseWhole(it->second, v) || !(v >= lo && v <= hi))
        badOption(key, "a number in [" + formatNumber(lo, 6) + ", " + formatNumber(hi, 6) + "]", it->second);
    value = float(v);
}

bool daylightPortalsOption(const RenderSettings& settings, bool byDefault) {
    const auto it = settings.options.find("daylight_portals");
    if (it == settings.options.end()) return byDefault;
    if (it->second == "on") return true;
    if (it->second == "off") return false;
    throw std::invalid_argument("option daylight_portals must be on or off, got '" + it->second + "'");
}

LightSelection lightSelectionOption(const RenderSettings& settings) {
    const auto it = settings.options.find("light_sampler");
    if (it == settings.options.end()) return kDefaultLightSelection;
    if (it->second == "power") return LightSelection::Power;
    if (it->second == "tree") return LightSelection::Tree;
    throw std::invalid_argument("option light_sampler must be power or tree, got '" + it->second + "'");
}

}  // namespace lucerna
