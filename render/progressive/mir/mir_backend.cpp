#include "render/progressive/mir/mir_backend.h"

#include "core/number_format.h"
#include "render/backend/tracing_backend.h"
#include "render/progressive/mir/mir_settings.h"
#include "render/vpl/mir_path.h"
#include "render/vpl/tile_scheduler.h"

#include <cstdio>

namespace lucerna {

namespace {

struct GeometricVpls {
    std::vector<Vpl> vpls;
    std::vector<int> counts;  // k_i
};

// One film half's chain and its Pc estimate.
struct MirChain {
    MultipleTryMetropolis<MirPath> mtm;
    Rng rng;
    int chosen = -1;  // which vertex of the current path is its path VPL
};

std::string number(double v) { return formatNumber(v, 6); }

class MirBackend final : public TracingBackend {
public:
    MirBackend(SceneSnapshot scene, const RenderSettings& settings)
        : TracingBackend(std::move(scene), settings), mir_(MirSettings::fromOptions(settings)) {}

    void prepare(TaskContext&) override {
        prepareSceneAndFilm();
        gatherer_ = std::make_unique<VplGatherer>(*scene_, mir_.gather);
        layout_ = mirPathLayout(mir_.gather, mir_.vpl);
        MetropolisParams params;
        params.dimension = layout_.dimension();
        params.tries = mir_.tries;
        params.largeStepProbability = mir_.largeStepProbability;
        const float maxG = gatherer_->maxG();
        for (int h = 0; h < 2; ++h) {
            auto target = [this, maxG](const std::vector<float>& u, MirPath& path) {
                return evaluateMirPath(*scene_, scene_->lights(), scene_->camera(), mir_.gather, mir_.vpl, maxG, layout_,
                                       u, path);
            };
            chains_.push_back(std::make_unique<MirChain>(
                MirChain{MultipleTryMetropolis<MirPath>(params, target), Rng(hashSeed(settings_.seed, h, 0x4d4952), 0)}));
        }
    }

    void renderPass(TaskContext& ctx, int pass) override {
        const int half = pass % 2;
        MirChain& chain = *chains_[size_t(half)];
        const GeometricVpls geo = samplePathVpls(chain);
        const double pc = chain.mtm.uniformMean();
        if (ctx.isCancelled()) return;
        const std::vector<float> scale = normalise(ctx, pass, geo, pc);
        if (ctx.isCancelled()) return;
        gather(ctx, pass, geo.vpls, scale);
        if (ctx.isCancelled()) return;
        film_->finishPass(half);
        pc_[size_t(half)] = pc;
        geometricVplCount_ += geo.vpls.size();
        ++passes_;
    }

    std::map<std::string, std::string> diagnostics() const override {
        std::map<std::string, std::string> d;
        if (chains_.size() == 2) {
            d["mir_acceptance_rate"] = number(0.5 * (chains_[0]->mtm.acceptanceRate() + chains_[1]->mtm.acceptanceRate()));
            d["mir_pc_half0"] = number(pc_[0]);
            d["mir_pc_half1"] = number(pc_[1]);
            d["mir_pc_samples"] = std::to_string(chains_[0]->mtm.uniformCount() + chains_[1]->mtm.uniformCount());
        }
        d["mir_tries"] = std::to_string(mir_.tries);
        d["mir_path_vpls_per_pass"] = std::to_string(mir_.pathVplsPerPass);
        d["mir_mean_geometric_vpls_per_pass"] = number(passes_ > 0 ? double(geometricVplCount_) / passes_ : 0.0);
        d["mir_dropped_vpls"] = std::to_string(droppedVpls_);
        return d;
    }

private:
    // Steps 1 to 3: n chain steps, one path VPL each, merged while the path VPL stays put.
    GeometricVpls samplePathVpls(MirChain& chain) {
        GeometricVpls geo;
        if (!chain.mtm.started() && !chain.mtm.start(chain.rng, mir_.startCandidates)) return geo;
        chain.mtm.sampleUniform(chain.rng, mir_.pcSamplesPerPass);
        for (int i = 0; i < mir_.pathVplsPerPass; ++i) {
            const bool moved = chain.mtm.step(chain.rng);
            if (moved || chain.chosen < 0 || geo.vpls.empty()) {
                if (moved || chain.chosen < 0) chain.chosen = choosePathVertex(chain.mtm.payload(), chain.rng.nextDouble());
                if (chain.chosen < 0) continue;
                geo.vpls.push_back(chain.mtm.payload().vpls[size_t(chain.chosen)]);
                geo.counts.push_back(1);
            } else {
                ++geo.counts.back();  // a rejected step: the same path VPL again
            }
        }
        return geo;
    }

    // Step 4: scale_i = (k_i Pc / n) / P'_i, P'_i measured on one camera sample per block.
    std::vector<float> normalise(TaskContext& ctx, int pass, const GeometricVpls& geo, double pc) {
        const size_t m = geo.vpls.size();
        std::vector<float> scale(m, 0.0f);
        if (m == 0 || !(pc > 0)) return scale;
        const Sensor& camera = scene_->camera();
        const int s = mir_.normalizationStride, w = camera.width(), h = camera.height();
        const int blocksX = (w + s - 1) / s, blocksY = (h + s - 1) / s;
        std::vector<std::vector<double>> rows(size_t(blocksY), std::vector<double>(m, 0.0));
        const uint64_t seed = hashSeed(settings_.seed, uint64_t(pass), 0x6e6f726d);
        ctx.parallelFor(0, blocksY, [&](int by) {
            std::vector<double>& row = rows[size_t(by)];
            for (int bx = 0; bx < blocksX; ++bx) {
                const int x0 = bx * s, y0 = by * s, bw = std::min(s, w - x0), bh = std::min(s, h - y0);
                Rng rng(seed, uint64_t(by) * uint64_t(blocksX) + uint64_t(bx));
                const V2f j = rng.next2D();
                std::vector<double> local(m, 0.0);
                gatherer_->addVplLuminance(camera.ray(float(x0) + j.x * float(bw), float(y0) + j.y * float(bh)), rng,
                                           geo.vpls, local);
                const double area = double(bw) * double(bh);
                for (size_t i = 0; i < m; ++i) row[i] += local[i] * area;
            }
        });
        const double pixels = double(w) * double(h);
        for (size_t i = 0; i < m; ++i) {
            double contribution = 0;  // P'_i: summed in a fixed order, whatever the thread count
            for (const auto& row : rows) contribution += row[i];
            contribution /= pixels;
            const double share = double(geo.counts[i]) * pc / double(mir_.pathVplsPerPass);
            const double si = contribution > 0 ? share / contribution : 0.0;
            if (contribution > 0 && std::isfinite(si)) scale[i] = float(si);
            else ++droppedVpls_;  // seen by the chain's camera point but by no measured pixel
        }
        return scale;
    }

    // Step 5.
    void gather(TaskContext& ctx, int pass, const std::vector<Vpl>& vpls, const std::vector<float>& scale) {
        const Sensor& camera = scene_->camera();
        const int half = pass % 2;
        const uint64_t passSeed = hashSeed(settings_.seed, uint64_t(pass));
        forEachPixel(camera.width(), camera.height(), mir_.gather.tileSize, ctx, [&](int x, int y) {
            Rng rng(passSeed, uint64_t(y) * uint64_t(camera.width()) + uint64_t(x));
            const V2f jitter = rng.next2D();
            Rgb L = gatherer_->radiance(camera.ray(float(x) + jitter.x, float(y) + jitter.y), rng, vpls, scale);
            if (!isFinite(L)) L = Rgb(0, 0, 0);
            film_->addSample(half, x, y, L);
        });
    }

    MirSettings mir_;
    std::unique_ptr<VplGatherer> gatherer_;
    MirPathLayout layout_;
    std::vector<std::unique_ptr<MirChain>> chains_;
    double pc_[2] = {0, 0};
    size_t geometricVplCount_ = 0;
    long long droppedVpls_ = 0;
    int passes_ = 0;
};

}  // namespace

std::unique_ptr<ProgressiveBackend> makeMirBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<MirBackend>(std::move(scene), settings);
}

}  // namespace lucerna
