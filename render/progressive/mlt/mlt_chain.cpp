#include "render/progressive/mlt/mlt_chain.h"

#include "render/trace/render_scene.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

ChainCounters& ChainCounters::operator+=(const ChainCounters& o) {
    steps += o.steps;
    accepted += o.accepted;
    largeSteps += o.largeSteps;
    largeAccepted += o.largeAccepted;
    causticSteps += o.causticSteps;
    causticAccepted += o.causticAccepted;
    variantSteps += o.variantSteps;
    variantAccepted += o.variantAccepted;
    largeStepSum += o.largeStepSum;
    return *this;
}

void depositContribution(const PathContribution& c, double weight, std::vector<FilmSplat>& out) {
    if (!(weight > 0.0) || !std::isfinite(weight)) return;
    // In double: weight is about 1 / c.f, beyond a float's range where c's values are tiny.
    for (const FilmSplat& s : c.deposits)
        out.push_back({s.x, s.y, Rgb(float(s.value.x * weight), float(s.value.y * weight), float(s.value.z * weight))});
}

namespace {
// The pixel deposit of the camera strategies, the target f, and no non-finite value.
void finish(const Rgb& L, float x, float y, PathContribution& out) {
    if (isFinite(L) && !isBlack(L)) out.deposits.push_back({int(x), int(y), L});
    for (const FilmSplat& s : out.deposits) out.f += std::max(0.0, double(luminance(s.value)));
    if (!std::isfinite(out.f)) {
        out.deposits.clear();
        out.f = 0;
    }
}
}  // namespace

V2f rasterPoint(const Sensor& camera, const V2f& u) {
    // Uniform over the whole raster; only a product rounded up to the edge is pulled back in (a
    // clamp to the last pixel's centre would pile the last half pixel onto one point, which on
    // an irradiance sensor's 2 x 2 block is a quarter of its directions).
    const float w = float(camera.width()), h = float(camera.height());
    return V2f(std::min(u.x * w, std::nextafter(w, 0.0f)), std::min(u.y * h, std::nextafter(h, 0.0f)));
}

void evaluatePath(BdptTracer& tracer, const Sensor& camera, PssSampler& sampler, PathContribution& out) {
    tracer.recordPaths(out.recordPaths ? &out.paths : nullptr);
    out.deposits.clear();
    out.f = 0;
    const V2f r = rasterPoint(camera, sampler.next2D());
    finish(tracer.sample(r.x, r.y, sampler, out.deposits), r.x, r.y, out);  // sample() appends the light splats
}

void evaluateLightSideAt(BdptTracer& tracer, float x, float y, PssSampler& sampler, PathContribution& out) {
    tracer.recordPaths(out.recordPaths ? &out.paths : nullptr);
    out.deposits.clear();
    out.f = 0;
    sampler.next2D();  // the raster point's numbers: keeps every later dimension where it was
    finish(tracer.sampleWithCameraSubpath(x, y, sampler, out.deposits), x, y, out);
}

void evaluatePathAt(BdptTracer& tracer, float x, float y, const std::optional<SurfacePoint>& primaryHit,
                    bool reuseLightSubpath, PssSampler& sampler, PathContribution& out) {
    tracer.recordPaths(out.recordPaths ? &out.paths : nullptr);
    out.deposits.clear();
    out.f = 0;
    sampler.next2D();  // the raster point's numbers: keeps every later dimension where it was
    finish(tracer.sample(x, y, primaryHit, reuseLightSubpath, sampler, out.deposits), x, y, out);
}

MltChain::MltChain(const RenderScene& scene, const MltSettings& settings, uint64_t bootstrapSeed, bool recordPaths)
    : camera_(scene.camera()), tracer_(scene, settings.bdpt),
      sampler_(bootstrapSeed, settings.sigma, settings.largeStepProbability),
      causticProbability_(settings.causticProbability) {
    current_.recordPaths = proposed_.recordPaths = recordPaths;
    sampler_.startLargeStep();
    evaluatePath(tracer_, camera_, sampler_, current_);
    sampler_.accept();
}

int MltChain::run(int steps, double scale, std::vector<FilmSplat>& out) {
    for (int i = 0; i < steps; ++i) mutate(scale, out);
    return steps;
}

void MltChain::mutate(double scale, std::vector<FilmSplat>& out) {
    // The kernel is chosen before the sampler draws anything: a mixture of kernels that each
    // keep f invariant keeps it invariant.
    const bool caustic = causticProbability_ > 0 && sampler_.rng().next1D() < causticProbability_;
    if (caustic) sampler_.startStreamStep(SampleStream::Light);
    else sampler_.startIteration();
    const bool large = sampler_.largeStep();
    evaluatePath(tracer_, camera_, sampler_, proposed_);
    // A chain that started on f = 0 (a black scene) moves to anything.
    const double a = current_.f > 0 ? std::min(1.0, proposed_.f / current_.f) : 1.0;
    if (proposed_.f > 0) depositContribution(proposed_, scale * a / proposed_.f, out);
    if (current_.f > 0) depositContribution(current_, scale * (1.0 - a) / current_.f, out);
    ++counters_.steps;
    counters_.largeSteps += large;
    counters_.causticSteps += caustic;
    if (large) counters_.largeStepSum += proposed_.f;
    if (sampler_.rng().nextDouble() < a) {
        sampler_.accept();
        std::swap(current_, proposed_);
        ++counters_.accepted;
        counters_.largeAccepted += large;
        counters_.causticAccepted += caustic;
    } else {
        sampler_.reject();
    }
}

}  // namespace lucerna
