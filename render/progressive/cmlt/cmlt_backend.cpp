#include "render/progressive/cmlt/cmlt_backend.h"

#include "core/number_format.h"
#include "render/backend/backend_options.h"
#include "render/progressive/cmlt/cmlt_chain.h"
#include "render/progressive/mlt/mlt_backend.h"

#include <map>
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

namespace {

// The acceptance of each of cmlt's kernels that ran, and how much of its path-space sub-chains
// stays on paths that no perturbation moves.
void addCmltDiagnostics(const std::map<std::string, long long>& counts, std::map<std::string, std::string>& d) {
    const auto count = [&](const char* name) {
        const auto it = counts.find(name);
        return it == counts.end() ? 0LL : it->second;
    };
    const auto rate = [](long long a, long long n) { return formatNumber(n > 0 ? double(a) / double(n) : 0.0, 6); };
    const long long lens = count("lens_steps"), pathLens = count("path_lens_steps"),
                    pathCaustic = count("path_caustic_steps"), still = count("path_still_steps");
    if (lens > 0) d["mlt_acceptance_lens"] = rate(count("lens_accepted"), lens);
    if (pathLens > 0) d["mlt_acceptance_path_lens"] = rate(count("path_lens_accepted"), pathLens);
    if (pathCaustic > 0) d["mlt_acceptance_path_caustic"] = rate(count("path_caustic_accepted"), pathCaustic);
    if (still > 0) d["mlt_path_unmoved"] = rate(still, pathLens + pathCaustic + still);
}

}  // namespace

std::unique_ptr<Backend> makeCmltBackend(SceneSnapshot scene, const RenderSettings& settings) {
    const CmltSettings cmlt = CmltSettings::fromOptions(settings);
    return makeMetropolisBackend(
        std::move(scene), settings, cmlt.mlt,
        [cmlt](const RenderScene& s, uint64_t seed) { return std::make_unique<CmltChain>(s, cmlt, seed); },
        addCmltDiagnostics);
}

}  // namespace lucerna
