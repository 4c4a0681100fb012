#include "render/preview/preview_mir_vpls.h"

#include "render/progressive/ir/vpl_gatherer.h"
#include "render/progressive/mir/metropolis.h"
#include "render/progressive/mir/mir_path.h"
#include "render/trace/camera.h"
#include "render/trace/rng.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

namespace lucerna {

namespace {

// Reads a range of the chain's point u in order; past its end, numbers come from a PCG32 seeded
// by a hash of the range, so a path stays a deterministic function of u (as mir_path.cpp does).
class PrimarySampleStream final : public SampleGenerator {
public:
    PrimarySampleStream(const float* begin, const float* end) : begin_(begin), next_(begin), end_(end) {}
    float next1D() override {
        if (next_ < end_) return *next_++;
        if (!padding_) {
            uint64_t h = 0x70726576u;
            for (const float* p = begin_; p < end_; ++p) h = hashSeed(h, std::bit_cast<uint32_t>(*p));
            padding_.emplace(h, 0);
        }
        return padding_->next1D();
    }
    V2f next2D() override {
        const float a = next1D();
        return V2f(a, next1D());
    }

private:
    const float* begin_;
    const float* next_;
    const float* end_;
    std::optional<Rng> padding_;
};

// mir_path.cpp's evaluateMirPath with the preview's lights and camera: f(u) = sum_k c_k(u), the
// luminance that the light sub-path's VPLs bring to the camera vertex.
double evaluatePath(const RenderScene& scene, const LightSampler& lights, const PinholeCamera& camera,
                    const GatherSettings& gather, const VplOptions& vpl, float maxG, const MirPathLayout& layout,
                    const std::vector<float>& u, MirPath& path) {
    path.vpls.clear();
    path.contribution.clear();
    const float* cam = u.data();
    const float* light = cam + layout.cameraDimensions;
    PrimarySampleStream cameraStream(cam, light);
    PrimarySampleStream lightStream(light, light + layout.lightDimensions);
    const V2f raster = cameraStream.next2D();
    const Ray ray = camera.ray(raster.x * float(camera.width()), raster.y * float(camera.height()));
    const CameraVertex cv = traceCameraVertex(scene, ray, cameraStream, gather.maxSpecularDepth);
    if (!cv.found) return 0.0;
    traceLightPath(scene, lights, lightStream, 1.0f, vpl, [&](const Vpl& v) { path.vpls.push_back(v); });
    double sum = 0;
    for (const Vpl& v : path.vpls) {
        const double ck = double(luminance(cv.throughput * vplContribution(scene, v, cv.receiver, maxG)));
        path.contribution.push_back(std::isfinite(ck) && ck > 0 ? ck : 0.0);
        sum += path.contribution.back();
    }
    return sum;
}

// Vertex k of the current path with probability c_k / f (-1 when f is 0).
int chooseVertex(const MirPath& p, Rng& rng) {
    double sum = 0;
    for (double c : p.contribution) sum += c;
    if (!(sum > 0)) return -1;
    double t = rng.nextDouble() * sum;
    for (size_t k = 0; k < p.contribution.size(); ++k) {
        if (t < p.contribution[k]) return int(k);
        t -= p.contribution[k];
    }
    for (size_t k = p.contribution.size(); k-- > 0;)
        if (p.contribution[k] > 0) return int(k);
    return -1;
}

}  // namespace

VplSet generateMirVpls(const RenderScene& scene, const LightSampler& lights, const Camera& cameraDesc, int width,
                       int height, const MirVplSettings& settings, uint64_t seed) {
    VplSet out;
    if (lights.empty() || settings.pathVpls <= 0) return out;
    GatherSettings gather;
    gather.clampFraction = settings.clampFraction;
    VplOptions vplOptions;
    vplOptions.maxBounces = settings.maxBounces;
    const PinholeCamera camera(cameraDesc, width, height);
    const VplGatherer gatherer(scene, gather);
    const float maxG = gatherer.maxG();
    const MirPathLayout layout = mirPathLayout(gather, vplOptions);
    MetropolisParams params;
    params.dimension = layout.dimension();
    params.tries = settings.tries;
    params.largeStepProbability = settings.largeStepProbability;
    MultipleTryMetropolis<MirPath> chain(params, [&](const std::vector<float>& u, MirPath& path) {
        return evaluatePath(scene, lights, camera, gather, vplOptions, maxG, layout, u, path);
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
            if (moved || chosen < 0) chosen = chooseVertex(chain.payload(), rng);
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
