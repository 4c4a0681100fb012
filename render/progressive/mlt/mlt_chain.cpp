#include "render/progressive/mlt/mlt_chain.h"

#include "render/trace/render_scene.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

namespace {
void deposit(const PathContribution& c, double weight, std::vector<FilmSplat>& out) {
    if (!(weight > 0.0)) return;
    for (const FilmSplat& s : c.deposits) out.push_back({s.x, s.y, s.value * float(weight)});
}
}  // namespace

void evaluatePath(BdptTracer& tracer, const PinholeCamera& camera, PssSampler& sampler, PathContribution& out) {
    out.deposits.clear();
    out.f = 0;
    const V2f r = sampler.next2D();
    const float x = std::min(r.x * float(camera.width()), float(camera.width()) - 0.5f);
    const float y = std::min(r.y * float(camera.height()), float(camera.height()) - 0.5f);
    const Rgb L = tracer.sample(x, y, sampler, out.deposits);  // appends the light splats
    if (isFinite(L) && !isBlack(L)) out.deposits.push_back({int(x), int(y), L});
    for (const FilmSplat& s : out.deposits) out.f += std::max(0.0, double(luminance(s.value)));
    if (!std::isfinite(out.f)) {
        out.deposits.clear();
        out.f = 0;
    }
}

MltChain::MltChain(const RenderScene& scene, const MltSettings& settings, uint64_t bootstrapSeed)
    : camera_(scene.camera()), tracer_(scene, settings.bdpt),
      sampler_(bootstrapSeed, settings.sigma, settings.largeStepProbability) {
    sampler_.startLargeStep();
    evaluatePath(tracer_, camera_, sampler_, current_);
    sampler_.accept();
}

void MltChain::run(int mutations, double scale, std::vector<FilmSplat>& out) {
    for (int i = 0; i < mutations; ++i) {
        sampler_.startIteration();
        const bool large = sampler_.largeStep();
        evaluatePath(tracer_, camera_, sampler_, proposed_);
        // A chain that started on f = 0 (a black scene) moves to anything.
        const double a = current_.f > 0 ? std::min(1.0, proposed_.f / current_.f) : 1.0;
        if (proposed_.f > 0) deposit(proposed_, scale * a / proposed_.f, out);
        if (current_.f > 0) deposit(current_, scale * (1.0 - a) / current_.f, out);
        ++steps_;
        largeSteps_ += large;
        if (large) largeStepSum_ += proposed_.f;
        if (sampler_.rng().nextDouble() < a) {
            sampler_.accept();
            std::swap(current_, proposed_);
            ++accepted_;
            largeAccepted_ += large;
        } else {
            sampler_.reject();
        }
    }
}

}  // namespace lucerna
