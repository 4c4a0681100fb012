#include "render/progressive/cmlt/cmlt_backend.h"

#include "render/progressive/backend_options.h"
#include "render/progressive/cmlt/cmlt_chain.h"
#include "render/progressive/mlt/mlt_backend.h"

#include <stdexcept>
#include <string>

namespace lucerna {

CmltSettings CmltSettings::fromOptions(const RenderSettings& settings) {
    CmltSettings s;
    s.mlt = MltSettings::fromOptions(settings, s.mlt);
    readOption(settings, "lens_steps", s.lensSteps, 0, 10000);
    readOption(settings, "tries", s.tries, 1, 64);
    readOption(settings, "sigma_pixels", s.sigmaPixels, 1e-3, 1e4);
    readOption(settings, "caustic_sigma", s.causticSigma, 1e-5, 1);
    readOption(settings, "caustic_steps", s.causticSteps, 0, 10000);
    readOption(settings, "path_lens_steps", s.pathLensSteps, 0, 10000);
    return s;
}

std::unique_ptr<ProgressiveBackend> makeCmltBackend(SceneSnapshot scene, const RenderSettings& settings) {
    const CmltSettings cmlt = CmltSettings::fromOptions(settings);
    return makeMetropolisBackend(std::move(scene), settings, cmlt.mlt, [cmlt](const RenderScene& s, uint64_t seed) {
        return std::make_unique<CmltChain>(s, cmlt, seed);
    });
}

}  // namespace lucerna
