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
    std::vector<int> counts;       // k_i
    std::vector<double> targets;   // c_k(u) of the VPL's path: its density up to Pc
};

// One film half's importance points, chain and Pc estimate.
struct MirChain {
    std::vector<CameraVertex> points;  // S
    double floor = 0;                  // the defensive floor of the target
    std::unique_ptr<MultipleTryMetropolis<MirPath>> mtm;
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
        for (int h = 0; h < 2; ++h) {
            auto chain = std::make_unique<MirChain>();
            chain->rng = Rng(hashSeed(settings_.seed, h, 0x4d4952), 0);
            chain->points = traceImportancePoints(*scene_, scene_->camera(), mir_.gather.maxSpecularDepth,
                                                  mir_.importancePoints, hashSeed(settings_.seed, h, 0x53));
            chain->floor = defensiveFloor(*chain);
            MirChain* c = chain.get();
            MetropolisParams params;
            params.dimension = layout_.lightDimensions;
            params.tries = mir_.tries;
            params.largeStepProbability = mir_.largeStepProbability;
            chain->mtm = std::make_unique<MultipleTryMetropolis<MirPath>>(
                params, [this, c](const std::vector<float>& u, MirPath& path) { return target(*c, c->floor, u, path); });
            chains_.push_back(std::move(chain));
        }
    }

    void renderPass(TaskContext& ctx, int pass) override {
        const int half = pass % 2;
        MirChain& chain = *chains_[size_t(half)];
        const GeometricVpls geo = samplePathVpls(chain);
        const double pc = chain.mtm->uniformMean();
        if (ctx.isCancelled()) return;
        gather(ctx, pass, geo.vpls, weights(geo, pc));
        if (ctx.isCancelled()) return;
        film_->finishPass(half);
        pc_[size_t(half)] = pc;
        geometricVplCount_ += geo.vpls.size();
        ++passes_;
    }

    std::map<std::string, std::string> diagnostics() const override {
        std::map<std::string, std::string> d;
        if (chains_.size() == 2) {
            d["mir_acceptance_rate"] = number(0.5 * (chains_[0]->mtm->acceptanceRate() + chains_[1]->mtm->acceptanceRate()));
            d["mir_pc_half0"] = number(pc_[0]);
            d["mir_pc_half1"] = number(pc_[1]);
            d["mir_pc_samples"] = std::to_string(chains_[0]->mtm->uniformCount() + chains_[1]->mtm->uniformCount());
            d["mir_importance_points"] = std::to_string(chains_[0]->points.size());
            d["mir_floor_half0"] = number(chains_[0]->floor);
        }
        d["mir_tries"] = std::to_string(mir_.tries);
        d["mir_path_vpls_per_pass"] = std::to_string(mir_.pathVplsPerPass);
        d["mir_mean_geometric_vpls_per_pass"] = number(passes_ > 0 ? double(geometricVplCount_) / passes_ : 0.0);
        return d;
    }

private:
    double target(const MirChain& chain, double floor, const std::vector<float>& u, MirPath& path) const {
        return evaluateMirLightPath(*scene_, scene_->lights(), chain.points, mir_.vpl, gatherer_->maxG(), floor, layout_,
                                    u, path);
    }

    // The floor: `defensive` times the mean importance of a VPL of uniformly drawn light paths
    // (pilot paths, not counted in Pc), so that the floor's share of the VPLs is about
    // defensive / (1 + defensive) where S sees the light, and all of them where it sees none.
    double defensiveFloor(MirChain& chain) const {
        std::vector<float> u(size_t(layout_.lightDimensions));
        MirPath path;
        double sum = 0;
        long long vertices = 0;
        for (int i = 0; i < mir_.pilotPaths; ++i) {
            for (float& x : u) x = chain.rng.next1D();
            sum += target(chain, 0.0, u, path);
            vertices += static_cast<long long>(path.vpls.size());
        }
        const double mean = vertices > 0 ? sum / double(vertices) : 0.0;
        return mean > 0 && std::isfinite(mean) ? mir_.defensive * mean : 1.0;
    }

    // Steps 1 and 2: n chain steps, one path VPL each, merged while the path VPL stays put.
    GeometricVpls samplePathVpls(MirChain& chain) {
        GeometricVpls geo;
        MultipleTryMetropolis<MirPath>& mtm = *chain.mtm;
        if (!mtm.started() && !mtm.start(chain.rng, mir_.startCandidates)) return geo;
        mtm.sampleUniform(chain.rng, mir_.pcSamplesPerPass);
        for (int i = 0; i < mir_.pathVplsPerPass; ++i) {
            const bool moved = mtm.step(chain.rng);
            if (moved || chain.chosen < 0 || geo.vpls.empty()) {
                if (moved || chain.chosen < 0) chain.chosen = choosePathVertex(mtm.payload(), chain.rng.nextDouble());
                if (chain.chosen < 0) continue;
                geo.vpls.push_back(mtm.payload().vpls[size_t(chain.chosen)]);
                geo.targets.push_back(mtm.payload().contribution[size_t(chain.chosen)]);
                geo.counts.push_back(1);
            } else {
                ++geo.counts.back();  // a rejected step: the same path VPL again
            }
        }
        return geo;
    }

    // Step 3: the importance-sampling weight of each geometric VPL. (u, k) has the density
    // c_k(u) / Pc, so VPL i, drawn k_i times in n steps, is weighted k_i Pc / (n c_k(u_i)).
    std::vector<float> weights(const GeometricVpls& geo, double pc) const {
        std::vector<float> w(geo.vpls.size(), 0.0f);
        for (size_t i = 0; i < w.size(); ++i) {
            const double wi = double(geo.counts[i]) * pc / (double(mir_.pathVplsPerPass) * geo.targets[i]);
            if (std::isfinite(wi) && wi > 0) w[i] = float(wi);
        }
        return w;
    }

    // Step 4.
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
    int passes_ = 0;
};

}  // namespace

std::unique_ptr<ProgressiveBackend> makeMirBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<MirBackend>(std::move(scene), settings);
}

}  // namespace lucerna
