#include "render/progressive/mir/mir_backend.h"

#include "core/number_format.h"
#include "render/progressive/gathering_backend.h"
#include "render/progressive/mir/mir_settings.h"
#include "render/progressive/mir/pc_balance.h"

#include <algorithm>
#include <array>

namespace lucerna {

namespace {

std::string number(double v) { return formatNumber(v, 6); }

class MirBackend final : public GatheringBackend {
public:
    MirBackend(SceneSnapshot scene, const RenderSettings& settings)
        // Daylight particles through the windows by default (daylight_portals): mir reached equal
        // error 1.9x and 4.7x sooner on two closed rooms of the daylit family, had 2.0 to 2.5x
        // less relmse at 10 s on the daylit office, and on the held-out room open to a bright
        // ground 1.2x more and 3.1x less (two seeds each; BENCHMARKS.md).
        : GatheringBackend(std::move(scene), settings, std::nullopt, true),
          mir_(MirSettings::fromOptions(settings, analyseFeatures(*snapshot_).hasDaylight())) {}

    void prepare(TaskContext&) override {
        prepareGatherer(mir_.gather);
        const Sensor& camera = scene_->camera();
        defaultPcSamples_ = std::max(256, camera.width() * camera.height() / 8);
        mir_.chain.pcSamples = mir_.pcSamplesPerPass >= 0 ? mir_.pcSamplesPerPass : defaultPcSamples_;
        pcSamplesNow_ = mir_.chain.pcSamples;
        vplFilm_ = std::make_unique<Film>(film_->width(), film_->height());
        for (int h = 0; h < 2; ++h)
            chains_.push_back(std::make_unique<MirChain>(*scene_, scene_->lights(), scene_->camera(), mir_.chain,
                                                         gatherer_->maxG(), hashSeed(settings_.seed, h, 0x4d4952)));
    }

    void renderPass(TaskContext& ctx, int pass) override {
        const int half = pass % 2;
        MirChain& chain = *chains_[size_t(half)];
        const VplSet vpls = chain.sampleUnitVpls(mir_.pathVplsPerPass);
        if (ctx.isCancelled()) return;
        // One camera sample per pixel, as `ir`; the VPLs' powers carry their weights but Pc,
        // which their film takes when read, so that every pass has the newest.
        gatherPass(ctx, pass, mir_.gather.tileSize, [&](uint64_t, uint64_t) -> const VplSet& { return vpls; },
                   vplFilm_.get());
        if (ctx.isCancelled()) return;
        film_->finishPass(half);
        vplFilm_->finishPass(half);
        vplFilm_->setHalfScale(half, chain.pc());
        sum_.reset();
        geometricVplCount_ += vpls.size();
        ++passes_;
        balancePcSamples();
    }

    // The direct light and the rest (film_) and the VPLs' light times Pc (vplFilm_'s half
    // scales), summed when read.
    const Film& film() const override {
        if (!vplFilm_) return *film_;
        if (!sum_) {
            const std::array<const Film*, 2> films{film_.get(), vplFilm_.get()};
            sum_ = std::make_unique<Film>(Film::sum(films));
        }
        return *sum_;
    }

    void rewriteFilms(const std::function<void(Film&)>& rewrite) override {
        rewrite(*film_);
        if (vplFilm_) rewrite(*vplFilm_);
        sum_.reset();
    }

    std::map<std::string, std::string> diagnostics() const override {
        std::map<std::string, std::string> d;
        if (chains_.size() == 2) {
            d["mir_acceptance_rate"] = number(0.5 * (chains_[0]->acceptanceRate() + chains_[1]->acceptanceRate()));
            d["mir_pc_half0"] = number(chains_[0]->pc());
            d["mir_pc_half1"] = number(chains_[1]->pc());
            d["mir_pc_relative_error"] =
                number(0.5 * std::sqrt(chains_[0]->pcRelativeVariance() + chains_[1]->pcRelativeVariance()));
            d["mir_pc_samples"] = std::to_string(chains_[0]->pcSamples() + chains_[1]->pcSamples());
            d["mir_importance_points"] = std::to_string(chains_[0]->importancePoints());
            d["mir_floor_half0"] = number(chains_[0]->floor());
        }
        d["mir_pc_samples_per_pass"] = std::to_string(pcSamplesNow_);
        d["mir_tries"] = std::to_string(mir_.chain.tries);
        d["mir_path_vpls_per_pass"] = std::to_string(mir_.pathVplsPerPass);
        d["mir_mean_geometric_vpls_per_pass"] = number(passes_ > 0 ? double(geometricVplCount_) / passes_ : 0.0);
        return d;
    }

private:
    // The cheap Pc samples of the passes to come, balanced against the gather's error
    // (pc_balance.h), unless the option pc_samples fixes them. On a closed sphere of albedo 0.9
    // Pc's error was most of the image's at the default's eighth of the pixel count a pass.
    void balancePcSamples() {
        // Measured again as the passes grow by a quarter: the measures cost a few passes over the
        // film, single-threaded, and settle as the render goes.
        if (mir_.pcSamplesPerPass >= 0 || passes_ < nextBalance_) return;
        nextBalance_ = std::max(passes_ + 1, int(1.25 * passes_));
        PcBalance b;
        measureImageTerms(*film_, *vplFilm_, 0.5 * (chains_[0]->pc() + chains_[1]->pc()), b);
        b.sampleRelativeVariance = 0.5 * (chains_[0]->pcSampleRelativeVariance() + chains_[1]->pcSampleRelativeVariance());
        // A pixel's gather: the camera ray, the residual's, a shadow ray and a BSDF ray per direct
        // sample, a shadow ray per VPL.
        b.passRays = double(film_->width()) * double(film_->height()) *
                     (2.0 + 2.0 * mir_.gather.directSamples + double(geometricVplCount_) / double(passes_));
        b.sampleRays = 0.5 * (chains_[0]->pcSampleRays() + chains_[1]->pcSampleRays());
        pcSamplesNow_ = balancedPcSamples(b, kLeastPcSamples, kMostPcSamplesTimesDefault * defaultPcSamples_,
                                          pcSamplesNow_);
        for (auto& chain : chains_) chain->setPcSamples(pcSamplesNow_);
    }

    static constexpr int kLeastPcSamples = 64;
    static constexpr int kMostPcSamplesTimesDefault = 16;

    MirSettings mir_;
    int defaultPcSamples_ = 0;
    int pcSamplesNow_ = 0;
    int nextBalance_ = 2;  // the pass count at which the balance is measured again
    std::vector<std::unique_ptr<MirChain>> chains_;  // one per film half
    std::unique_ptr<Film> vplFilm_;
    mutable std::unique_ptr<Film> sum_;  // film(), until the next pass
    size_t geometricVplCount_ = 0;
    int passes_ = 0;
};

}  // namespace

std::unique_ptr<Backend> makeMirBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<MirBackend>(std::move(scene), settings);
}

}  // namespace lucerna
