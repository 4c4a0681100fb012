#include "render/progressive/cmlt/cmlt_backend.h"

#include "render/progressive/cmlt/cmlt_chain.h"
#include "render/progressive/mlt/mlt_backend.h"

#include <stdexcept>
#include <string>

namespace lucerna {

CmltSettings CmltSettings::fromOptions(const RenderSettings& settings) {
    CmltSettings s;
    s.mlt = MltSettings::fromOptions(settings);
    const auto read = [&](const char* key, double lo, double hi, auto& value) {
        const auto it = settings.options.find(key);
        if (it == settings.options.end()) return;
        char* end = nullptr;
        const double v = std::strtod(it->second.c_str(), &end);
        if (end == it->second.c_str() || *end != '\0' || !(v >= lo && v <= hi))
            throw std::invalid_argument(std::string("option ") + key + " must be a number in [" + std::to_string(lo) +
                                        ", " + std::to_string(hi) + "], got '" + it->second + "'");
        value = static_cast<std::remove_reference_t<decltype(value)>>(v);
    };
    read("lens_steps", 0, 1e4, s.lensSteps);
    read("tries", 1, 64, s.tries);
    read("sigma_pixels", 1e-3, 1e4, s.sigmaPixels);
    return s;
}

std::unique_ptr<ProgressiveBackend> makeCmltBackend(SceneSnapshot scene, const RenderSettings& settings) {
    const CmltSettings cmlt = CmltSettings::fromOptions(settings);
    return makeMetropolisBackend(std::move(scene), settings, cmlt.mlt, [cmlt](const RenderScene& s, uint64_t seed) {
        return std::make_unique<CmltChain>(s, cmlt, seed);
    });
}

}  // namespace lucerna
