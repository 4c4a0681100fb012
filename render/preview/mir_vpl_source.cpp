#include "render/preview/mir_vpl_source.h"

#include "render/trace/camera.h"
#include "render/vpl/vpl_contribution.h"

namespace lucerna {

VplSet generateMirVpls(const RenderScene& scene, const LightSampler& lights, const Camera& cameraDesc, int width,
                       int height, const MirVplSettings& settings, uint64_t seed) {
    if (lights.empty() || settings.pathVpls <= 0) return {};
    const Sensor camera(PinholeCamera(cameraDesc, width, height));
    MirChain mir(scene, lights, camera, settings.chain, geometricClampBound(scene, settings.clampFraction), seed);
    return mir.sampleVpls(settings.pathVpls);
}

}  // namespace lucerna
