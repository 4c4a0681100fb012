#include "render/vpl/gather_settings.h"

#include "render/backend/backend_options.h"

namespace lucerna {

GatherSettings gatherSettingsFromOptions(const RenderSettings& settings, GatherSettings defaults) {
    GatherSettings g = defaults;
    readOption(settings, "clamp", g.clampFraction, 0.0, 1e3);
    int compensate = g.compensate ? 1 : 0;
    readOption(settings, "compensate", compensate, 0, 1);
    g.compensate = compensate == 1;
    readOption(settings, "residual_vpls", g.residualVplShare, 0.0, 1.0);
    readOption(settings, "direct_samples", g.directSamples, 1, 1024);
    return g;
}

}  // namespace lucerna
