#include "render/progressive/ir/ir_settings.h"

#include <charconv>
#include <stdexcept>

namespace lucerna {

namespace {
template <class T>
bool parseNumber(const std::string& text, T& out) {
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && ptr == text.data() + text.size();
}
}  // namespace

void readIntOption(const RenderSettings& settings, const char* key, int& value, int lo) {
    const auto it = settings.options.find(key);
    if (it == settings.options.end()) return;
    int v = 0;
    if (!parseNumber(it->second, v) || v < lo)
        throw std::invalid_argument(std::string("option ") + key + " must be an integer >= " + std::to_string(lo));
    value = v;
}

void readFloatOption(const RenderSettings& settings, const char* key, float& value, float lo, float hi) {
    const auto it = settings.options.find(key);
    if (it == settings.options.end()) return;
    float v = 0;
    if (!parseNumber(it->second, v) || !(v >= lo && v <= hi))
        throw std::invalid_argument(std::string("option ") + key + " must be a number in [" + std::to_string(lo) +
                                    ", " + std::to_string(hi) + "]");
    value = v;
}

GatherSettings gatherSettingsFromOptions(const RenderSettings& settings) {
    GatherSettings g;
    readFloatOption(settings, "clamp", g.clampFraction, 0.0f, 1e3f);
    int compensate = g.compensate ? 1 : 0;
    readIntOption(settings, "compensate", compensate, 0);
    if (compensate > 1) throw std::invalid_argument("option compensate must be 0 or 1");
    g.compensate = compensate == 1;
    return g;
}

IrSettings IrSettings::fromOptions(const RenderSettings& settings) {
    IrSettings s;
    s.gather = gatherSettingsFromOptions(settings);
    readIntOption(settings, "vpl_paths", s.lightPathsPerPass, 1);
    readIntOption(settings, "max_bounces", s.vpl.maxBounces, 1);
    return s;
}

}  // namespace lucerna
