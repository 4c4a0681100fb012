#include "render/progressive/mlt/mlt_backend.h"

#include "core/number_format.h"
#include "render/backend/backend_options.h"
#include "render/backend/film.h"
#include "render/progressive/tracing_backend.h"
#include "render/progressive/mlt/mlt_chain.h"
#include "render/trace/discrete_distribution.h"
#include "render/trace/render_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace lucerna {

namespace {

std::string number(double v) { return formatNumber(v, 6); }

// One film half: its normalisation and its chains.
struct ChainSet {
    double bootstrapSum = 0;  // of f over the bootstrap samples
    long long bootstrapCount = 0;
    std::vector<double> firstSamples;  // f of a deferred bootstrap's first samples (completeBootstrap)
    std::vector<std::unique_ptr<MltChain>> chains;

    ChainCounters counters() const {
        ChainCounters total;
        for (const auto& c : chains) total += c->counters();
        return total;
    }
    void addVariantCounts(std::map<std::string, long long>& total) const {
        for (const auto& c : chains)
            for (const auto& [name, count] : c->variantCounts()) total[name] += count;
    }
    // b = int f du: the mean of f over every uniform sample so far, the bootstrap's and the
    // chains' large steps'.
    double b() const {
        const ChainCounters c = counters();
        const long long count = bootstrapCount + c.largeSteps;
        return count > 0 ? (bootstrapSum + c.largeStepSum) / double(count) : 0.0;
    }
};

class MetropolisBackend final : public TracingBackend {
public:
    MetropolisBackend(SceneSnapshot scene, const RenderSettings& settings, const MltSettings& mlt, ChainFactory make,
                      VariantDiagnostics variantDiagnostics)
        // Lights chosen as the bdpt sampler chooses them (`light_sampler`, the tree by default).
        : TracingBackend(std::move(scene), settings), mlt_(mlt), makeChain_(std::move(make)),
          variantDiagnostics_(std::move(variantDiagnostics)) {}

    void prepare(TaskContext& ctx) override {
        prepareSceneAndFilm();
        const Sensor& camera = scene_->camera();
        const double perPixel = std::ceil(double(mlt_.firstBootstrapPerPixel) * camera.width() * camera.height());
        const int first = mlt_.firstBootstrapPerPixel > 0
                              ? int(std::clamp(perPixel, double(std::min(kLeastFirstBootstrap, mlt_.bootstrapSamples)),
                                               double(mlt_.bootstrapSamples)))
                              : mlt_.bootstrapSamples;
        for (int half = 0; half < 2 && !ctx.isCancelled(); ++half) halves_[half] = bootstrap(ctx, half, first);
    }

    void completePreparation(TaskContext& ctx) override {
        for (int half = 0; half < 2 && !ctx.isCancelled(); ++half) completeBootstrap(ctx, half, halves_[half]);
    }

    double deferredPreparationSeconds() const override { return deferredSeconds_; }

    void renderPass(TaskContext& ctx, int pass) override {
        const int half = pass % 2;
        ChainSet& set = halves_[half];
        if (pass >= 2) completeBootstrap(ctx, half, set);
        const Sensor& camera = scene_->camera();
        const double pixels = double(camera.width()) * double(camera.height());
        const int n = int(set.chains.size());
        if (n == 0) {  // nothing reaches the camera: the image is black
            film_->finishPass(half);
            return;
        }
        const int perChain = std::max(1, int(std::ceil(double(mlt_.mutationsPerPixel) * pixels / n)));
        // Deposits carry weight 1 per step; the pass's image is W H / (steps made) times their sum.
        std::vector<std::vector<FilmSplat>> deposits(static_cast<size_t>(n));
        std::vector<int> made(static_cast<size_t>(n), 0);
        ctx.parallelFor(0, n, [&](int c) {
            // Cancellation is checked between chains: a chain's share is a few milliseconds.
            if (!ctx.isCancelled()) made[size_t(c)] = set.chains[size_t(c)]->run(perChain, 1.0, deposits[size_t(c)]);
        });
        if (ctx.isCancelled()) return;
        long long steps = 0;
        for (int m : made) steps += m;
        const float scale = float(pixels / double(std::max(1LL, steps)));
        for (auto& list : deposits) {
            for (FilmSplat& d : list) d.value *= scale;
            film_->addSplats(half, list);
        }
        film_->finishPass(half);
        film_->setHalfScale(half, set.b());
    }

    std::map<std::string, std::string> diagnostics() const override {
        std::map<std::string, std::string> d;
        ChainCounters c = halves_[0].counters();
        c += halves_[1].counters();
        const auto rate = [](long long a, long long n) { return n > 0 ? double(a) / double(n) : 0.0; };
        const long long smallSteps = c.steps - c.largeSteps - c.causticSteps - c.variantSteps;
        d["mlt_acceptance_small"] =
            number(rate(c.accepted - c.largeAccepted - c.causticAccepted - c.variantAccepted, smallSteps));
        if (c.causticSteps > 0) d["mlt_acceptance_caustic"] = number(rate(c.causticAccepted, c.causticSteps));
        d["mlt_acceptance_large"] = number(rate(c.largeAccepted, c.largeSteps));
        if (variantDiagnostics_) {
            std::map<std::string, long long> counts;
            halves_[0].addVariantCounts(counts);
            halves_[1].addVariantCounts(counts);
            variantDiagnostics_(counts, d);
        }
        // The spread between the independent halves (each its own chains and b): how far their
        // image means disagree, relative to the combined mean.
        const double m0 = film_->halfImage(0).mean(), m1 = film_->halfImage(1).mean();
        if (m0 + m1 > 0) d["mlt_half_mean_spread"] = number(std::abs(m0 - m1) / (0.5 * (m0 + m1)));
        d["mlt_b_half0"] = number(halves_[0].b());
        d["mlt_b_half1"] = number(halves_[1].b());
        d["mlt_chains"] = std::to_string(mlt_.chains);
        d["mlt_bootstrap_samples"] = std::to_string(halves_[0].bootstrapCount + halves_[1].bootstrapCount);
        return d;
    }

private:
    // b = mean of f over the half's first `count` uniform samples, and chains started from samples
    // drawn in proportion to f among them (each replays its sample from the same seed).
    ChainSet bootstrap(TaskContext& ctx, int half, int count) { return seeded(ctx, half, uniformSamples(ctx, half, 0, count)); }

    // The set of the half's first f.size() uniform samples: b and the chains. The same samples
    // start the same chains.
    ChainSet seeded(TaskContext& ctx, int half, std::vector<double> f) {
        ChainSet set;
        for (double v : f) set.bootstrapSum += v;
        set.bootstrapCount = (long long)f.size();
        const DiscreteDistribution distribution(f);
        if (!distribution.empty() && !ctx.isCancelled()) {
            Rng rng(hashSeed(settings_.seed, uint64_t(half), 0x6368));
            for (int c = 0; c < mlt_.chains; ++c)
                set.chains.push_back(makeChain_(*scene_, sampleSeed(half, int(distribution.sample(rng.next1D())))));
        }
        if (set.bootstrapCount < mlt_.bootstrapSamples) set.firstSamples = std::move(f);
        return set;
    }

    // The bootstrap's samples past the first pass's (firstBootstrapPerPixel), and the chains
    // started again among all of them: the b and the chains of the whole bootstrap drawn at once,
    // less the large steps of the passes so far. Chains seeded among the first samples only left
    // cmlt on the door 4% worse (auto at 30 s, 6 of 7 seeds worse).
    void completeBootstrap(TaskContext& ctx, int half, ChainSet& set) {
        if (set.bootstrapCount >= mlt_.bootstrapSamples) return;
        const auto start = std::chrono::steady_clock::now();
        const std::vector<double> rest = uniformSamples(ctx, half, int(set.bootstrapCount), mlt_.bootstrapSamples);
        if (!ctx.isCancelled()) {
            std::vector<double> f = std::move(set.firstSamples);
            f.insert(f.end(), rest.begin(), rest.end());
            set = seeded(ctx, half, std::move(f));
        }
        deferredSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    // f of uniform samples begin, ..., end - 1 of a half, each from its own seed.
    std::vector<double> uniformSamples(TaskContext& ctx, int half, int begin, int end) const {
        constexpr int blocks = 64;
        std::vector<double> f(size_t(std::max(0, end - begin)), 0.0);
        ctx.parallelFor(0, blocks, [&](int block) {
            BdptTracer tracer(*scene_, mlt_.bdpt);
            PathContribution c;
            for (int i = begin + block; i < end && !ctx.isCancelled(); i += blocks) {
                PssSampler sampler(sampleSeed(half, i), mlt_.sigma, mlt_.largeStepProbability);
                sampler.startLargeStep();
                evaluatePath(tracer, scene_->camera(), sampler, c);
                f[size_t(i - begin)] = c.f;
            }
        });
        return f;
    }

    uint64_t sampleSeed(int half, int i) const { return hashSeed(settings_.seed, uint64_t(half), uint64_t(i) + 1); }

    // The fewest bootstrap samples a half starts its chains from.
    static constexpr int kLeastFirstBootstrap = 4096;

    MltSettings mlt_;
    ChainFactory makeChain_;
    VariantDiagnostics variantDiagnostics_;
    ChainSet halves_[2];
    double deferredSeconds_ = 0;  // in completeBootstrap
};

}  // namespace

MltSettings MltSettings::fromOptions(const RenderSettings& settings, MltSettings defaults) {
    MltSettings s = std::move(defaults);
    s.bdpt = BdptSettings::fromOptions(settings);
    readOption(settings, "bootstrap", s.bootstrapSamples, 1, 100000000);
    // A quarter of a pass's samples before a pilot's pass: the whole bootstrap of auto's four
    // Metropolis replicas made a 30 s render of the closed sphere of albedo 0.9, where both lose
    // by far, take 48 s (32 s deferred); the door, where cmlt carries, 32.8 s (31.7 s), at the
    // same error over 8 seeds (BENCHMARKS.md, R96).
    if (settings.deferPreparation) s.firstBootstrapPerPixel = 0.25f;
    readOption(settings, "bootstrap_first_per_pixel", s.firstBootstrapPerPixel, 0, 1e4);
    readOption(settings, "chains", s.chains, 1, 1000000);
    readOption(settings, "mutations", s.mutationsPerPixel, 1e-3, 1e4);
    readOption(settings, "large_step", s.largeStepProbability, 0, 1);
    readOption(settings, "sigma", s.sigma, 1e-5, 0.5);
    readOption(settings, "caustic", s.causticProbability, 0, 1);
    return s;
}

std::unique_ptr<Backend> makeMetropolisBackend(SceneSnapshot scene, const RenderSettings& settings,
                                                          const MltSettings& mlt, ChainFactory makeChain,
                                                          VariantDiagnostics variantDiagnostics) {
    return std::make_unique<MetropolisBackend>(std::move(scene), settings, mlt, std::move(makeChain),
                                               std::move(variantDiagnostics));
}

std::unique_ptr<Backend> makeMltBackend(SceneSnapshot scene, const RenderSettings& settings) {
    const MltSettings mlt = MltSettings::fromOptions(settings);
    return makeMetropolisBackend(std::move(scene), settings, mlt, [mlt](const RenderScene& s, uint64_t seed) {
        return std::make_unique<MltChain>(s, mlt, seed);
    });
}

}  // namespace lucerna
