#include "render/preview/per_light_vpls.h"

#include "render/trace/rng.h"
#include "render/trace/sample_generator.h"
#include "render/vpl/instant_radiosity.h"

namespace lucerna {

LightSampler singleLightSampler(const RenderScene& scene, const DeltaLight* delta) {
    std::vector<EmitterTriangle> emitters;
    std::vector<DeltaLight> deltas;
    if (delta)
        deltas.push_back(*delta);
    else
        emitters = scene.lights().emitters();
    return LightSampler(std::move(emitters), std::move(deltas), scene.metersPerUnit(), scene.boundsCenter(),
                        scene.boundsRadius(), scene.triangleCount());
}

namespace {
// Independent uniform numbers for the shared light tracer.
class RngGenerator final : public SampleGenerator {
public:
    explicit RngGenerator(uint64_t seed) : rng_(seed, 0x5eedULL) {}
    float next1D() override { return rng_.next1D(); }
    V2f next2D() override { return rng_.next2D(); }
    uint32_t nextUint() { return rng_.nextUint(); }

private:
    Rng rng_;
};
}  // namespace

VplSet traceVpls(const RenderScene& scene, const LightSampler& source, int count, uint64_t seed, int maxBounces) {
    VplSet vpls;
    if (source.empty() || count <= 0) return vpls;
    VplOptions options;
    options.maxBounces = maxBounces;
    RngGenerator u(seed);
    // Paths until `count` VPLs are stored: the count, not the path number, sets a frame's cost.
    const long maxPaths = 64L * count;
    long paths = 0;
    while (int(vpls.size()) < count && paths < maxPaths) {
        ++paths;
        traceLightPath(scene, source, u, 1.0f, options, [&](const Vpl& v) { vpls.push_back(v); });
    }
    // A path may leave several VPLs: dropping a uniformly chosen surplus and scaling the rest up
    // keeps the set's expectation (the last path's VPLs would otherwise overshoot the count).
    double keepScale = 1.0;
    if (int(vpls.size()) > count) {
        for (size_t i = 0; i < size_t(count); ++i) std::swap(vpls[i], vpls[i + u.nextUint() % (vpls.size() - i)]);
        keepScale = double(vpls.size()) / double(count);
        vpls.resize(size_t(count));
    }
    const float scale = float(keepScale / double(paths));
    for (Vpl& v : vpls) v.power *= scale;
    return vpls;
}

}  // namespace lucerna
