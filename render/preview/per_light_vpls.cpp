#include "render/preview/per_light_vpls.h"

#include <algorithm>
#include <cmath>

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

namespace {

// `count` VPLs resampled from `all` in proportion to their power (systematic resampling: VPL i
// is chosen floor or ceil of count p_i times, count p_i on average), each carrying
// (times chosen) sum / count of the power: an unbiased set of equal-power VPLs. Equal powers
// keep any one VPL from lighting its neighbourhood much more than the rest (the blotches of
// instant radiosity), and many paths resampled to few VPLs keep a frame's total light steady.
VplSet resampleByPower(const VplSet& all, int count, float u0) {
    double total = 0;
    for (const Vpl& v : all) total += std::max(1e-30f, luminance(v.power));
    const double step = total / count;
    VplSet out;
    double next = u0 * step, acc = 0;
    for (const Vpl& v : all) {
        const double lum = std::max(1e-30f, luminance(v.power));
        acc += lum;
        int chosen = 0;
        while (next < acc && int(out.size()) + chosen < count) ++chosen, next += step;
        if (chosen == 0) continue;
        Vpl kept = v;
        kept.power = v.power * float(chosen * step / lum);
        out.push_back(kept);
    }
    return out;
}

}  // namespace

VplSet traceVpls(const RenderScene& scene, const LightSampler& source, int count, uint64_t seed, int maxBounces) {
    if (source.empty() || count <= 0) return {};
    VplOptions options;
    options.maxBounces = maxBounces;
    // The pilot draws from its own stream, so the path count it sets is independent of the
    // paths that are kept (a fixed count as far as they are concerned).
    RngGenerator pilot(hashSeed(seed, 0x9170ULL));
    constexpr int kPilotPaths = 32;
    long pilotVpls = 0;
    for (int i = 0; i < kPilotPaths; ++i)
        traceLightPath(scene, source, pilot, 1.0f, options, [&](const Vpl&) { ++pilotVpls; });
    // Paths for kOversampling times the VPLs kept: tracing is cheap next to a shadow map per VPL,
    // and the frame's total indirect light is then as steady as that many paths make it (in a
    // closed room of albedo 0.8, 256 VPLs come from ~55 paths: +-5% a frame). A light whose
    // paths leave nothing in the pilot gets 64 paths a VPL.
    constexpr double kOversampling = 16.0;
    const double perPath = pilotVpls > 0 ? double(pilotVpls) / kPilotPaths : kOversampling / 64.0;
    const long paths = std::clamp(std::lround(kOversampling * count / perPath), 1L, 64L * count);
    RngGenerator u(seed);
    VplSet all;
    for (long p = 0; p < paths; ++p)
        traceLightPath(scene, source, u, 1.0f, options, [&](const Vpl& v) { all.push_back(v); });
    const float inverse = float(1.0 / double(paths));
    for (Vpl& v : all) v.power *= inverse;
    if (int(all.size()) <= count) return all;
    return resampleByPower(all, count, u.next1D());
}

}  // namespace lucerna
