#include "render/preview/mir_vpl_source.h"

#include "render/trace/camera.h"
#include "render/trace/rng.h"
#include "render/vpl/metropolis.h"
#include "render/vpl/mir_path.h"
#include "render/vpl/vpl_gatherer.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

VplSet generateMirVpls(const RenderScene& scene, const LightSampler& lights, const Camera& cameraDesc, int width,
                       int height, const MirVplSettings& settings, uint64_t seed) {
    VplSet out;
    if (lights.empty() || settings.pathVpls <= 0) return out;
    GatherSettings gather;
    gather.clampFraction = settings.clampFraction;
    VplOptions vplOptions;
    vplOptions.maxBounces = settings.maxBounces;
    const Sensor camera(PinholeCamera(cameraDesc, width, height));
    const VplGatherer gatherer(scene, gather);
    const float maxG = gatherer.maxG();
    const MirPathLayout layout = mirPathLayout(gather, vplOptions);
    MetropolisParams params;
    params.dimension = layout.dimension();
    params.tries = settings.tries;
    params.largeStepProbability = settings.largeStepProbability;
    MultipleTryMetropolis<MirPath> chain(params, [&](const std::vector<float>& u, MirPath& path) {
        return evaluateMirPath(scene, lights, camera, gather, vplOptions, maxG, layout, u, path);
    });
    Rng rng(seed, 0x4d495250ULL);
    if (!chain.start(rng, settings.startCandidates)) return out;
    chain.sampleUniform(rng, settings.pcSamples);

    // Steps 1 and 2: one path VPL per step, merged while the chain stays put.
    std::vector<int> counts;
    int chosen = -1;
    for (int i = 0; i < settings.pathVpls; ++i) {
        const bool moved = chain.step(rng);
        if (moved || chosen < 0 || out.empty()) {
            if (moved || chosen < 0) chosen = choosePathVertex(chain.payload(), rng.nextDouble());
            if (chosen < 0) continue;
            out.push_back(chain.payload().vpls[size_t(chosen)]);
            counts.push_back(1);
        } else {
            ++counts.back();  // a rejected step: the same path VPL again
        }
    }
    const double pc = chain.uniformMean();

    // Step 3: P'_i, the mean image luminance of VPL i at unit scale, from stratified camera samples.
    std::vector<double> contribution(out.size(), 0.0);
    const int samples = std::max(1, settings.normalizationSamples);
    const int sx = std::max(1, int(std::lround(std::sqrt(double(samples) * width / height))));
    const int sy = std::max(1, samples / sx);
    Rng camRng(seed, 0x6e6f726dULL);
    for (int j = 0; j < sy; ++j)
        for (int i = 0; i < sx; ++i) {
            const V2f r = camRng.next2D();
            const Ray ray = camera.ray((float(i) + r.x) * float(width) / float(sx),
                                       (float(j) + r.y) * float(height) / float(sy));
            gatherer.addVplLuminance(ray, camRng, out, contribution);
        }
    VplSet kept;
    for (size_t i = 0; i < out.size(); ++i) {
        const double measured = contribution[i] / double(sx * sy);
        const double share = double(counts[i]) * pc / double(settings.pathVpls);
        const double scale = measured > 0 ? share / measured : 0.0;
        // A VPL no camera sample saw lights nothing measurable: dropped, as the backend does.
        if (!(scale > 0) || !std::isfinite(scale)) continue;
        Vpl v = out[i];
        v.power *= float(scale);
        kept.push_back(v);
    }
    return kept;
}

}  // namespace lucerna
