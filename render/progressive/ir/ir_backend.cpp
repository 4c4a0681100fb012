#include "render/progressive/ir/ir_backend.h"

#include "render/progressive/gathering_backend.h"
#include "render/progressive/ir/ir_settings.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace lucerna {

namespace {

class IrBackend final : public GatheringBackend {
public:
    IrBackend(SceneSnapshot scene, const RenderSettings& settings)
        : GatheringBackend(std::move(scene), settings), ir_(IrSettings::fromOptions(settings)) {}

    void prepare(TaskContext&) override {
        prepareGatherer(ir_.gather);
        // Each set is gathered by 64 pixels or more, so that particles stay cheap next to the
        // gather on small films (a calculation grid's sensors).
        const Sensor& camera = scene_->camera();
        const double pixels = double(camera.width()) * double(camera.height());
        interleave_ = std::clamp(int(std::sqrt(pixels / 64.0)), 1, ir_.interleave);
    }

    void renderPass(TaskContext& ctx, int pass) override {
        // Fresh VPL sets per pass, independent of each other and of every other pass; each pixel
        // gathers one drawn by a hash of the pixel and the pass: white noise in the image, where
        // a fixed m x m pattern showed as a texture for the first passes.
        const int m = interleave_;
        std::vector<VplSet> sets(size_t(m) * size_t(m));
        for (size_t k = 0; k < sets.size(); ++k) {
            sets[k] = generateVpls(*scene_, ir_.lightPathsPerPass, hashSeed(settings_.seed, uint64_t(pass), 0x1a1 + k),
                                   ir_.vpl);
            vplCount_ += sets[k].size();
        }
        gatherPass(ctx, pass, ir_.gather.tileSize, [&](uint64_t passSeed, uint64_t pixel) -> const VplSet& {
            return sets[size_t(hashSeed(passSeed, pixel, 0x696c76) % sets.size())];
        });
        if (!ctx.isCancelled()) {
            film_->finishPass(pass % 2);
            ++passes_;
        }
    }

    std::map<std::string, std::string> diagnostics() const override {
        std::map<std::string, std::string> d;
        d["ir_light_paths_per_pass"] = std::to_string(ir_.lightPathsPerPass);
        d["ir_interleave"] = std::to_string(interleave_);
        d["ir_mean_vpls_per_set"] =
            std::to_string(passes_ > 0 ? double(vplCount_) / passes_ / double(interleave_ * interleave_) : 0.0);
        d["ir_clamp_fraction"] = std::to_string(ir_.gather.clampFraction);
        d["ir_compensate"] = ir_.gather.compensate ? "1" : "0";
        return d;
    }

private:
    IrSettings ir_;
    int interleave_ = 1;  // m: m^2 sets a pass
    size_t vplCount_ = 0;
    int passes_ = 0;
};

}  // namespace

std::unique_ptr<Backend> makeIrBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<IrBackend>(std::move(scene), settings);
}

}  // namespace lucerna
