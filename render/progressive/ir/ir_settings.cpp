#include "render/progressive/ir/ir_settings.h"

#include "render/backend/backend_options.h"

namespace lucerna {

IrSettings IrSettings::fromOptions(const RenderSettings& settings) {
    IrSettings s;
    s.gather = gatherSettingsFromOptions(settings);
    readOption(settings, "vpl_paths", s.lightPathsPerPass, 1);
    readOption(settings, "interleave", s.interleave, 1, 16);
    readOption(settings, "max_bounces", s.vpl.maxBounces, 1);
    return s;
}

}  // namespace lucerna
