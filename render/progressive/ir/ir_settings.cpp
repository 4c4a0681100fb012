#include "render/progressive/ir/ir_settings.h"

#include "render/progressive/backend_options.h"

#include <stdexcept>

namespace lucerna {

GatherSettings gatherSettingsFromOptions(const RenderSettings& settings) {
    GatherSettings g;
    readOption(settings, "clamp", g.clampFraction, 0.0, 1e3);
    int compensate = g.compensate ? 1 : 0;
    readOption(settings, "compensate", compensate, 0, 1);
    g.compensate = compensate == 1;
    return g;
}

IrSettings IrSettings::fromOptions(const RenderSettings& settings) {
    IrSettings s;
    s.gather = gatherSettingsFromOptions(settings);
    readOption(settings, "vpl_paths", s.lightPathsPerPass, 1);
    readOption(settings, "max_bounces", s.vpl.maxBounces, 1);
    return s;
}

}  // namespace lucerna
