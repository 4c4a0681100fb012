#include "render/backend/light_layers/layered_backend.h"

#include "render/backend/light_layers/light_groups.h"
#include "render/trace/rng.h"

#include <stdexcept>

namespace lucerna {

namespace {

class LayeredBackend final : public Backend {
public:
    LayeredBackend(BackendFactory base, SceneSnapshot scene, const RenderSettings& settings)
        : groups_(lightGroups(*scene)), combined_(0, 0) {
        if (groups_.size() > kMaxLightLayers) throw std::invalid_argument(lightLayerLimitMessage(groups_.size()));
        for (size_t g = 0; g < groups_.size(); ++g) {
            RenderSettings s = settings;
            s.seed = hashSeed(settings.seed, g, 0x1a7e5);  // layers sample independently
            layers_.push_back(base(std::make_shared<const Scene>(sceneLitBy(*scene, groups_[g])), s));
        }
        if (layers_.empty()) layers_.push_back(base(std::move(scene), settings));
    }

    void prepare(TaskContext& ctx) override {
        for (auto& layer : layers_) {
            if (ctx.isCancelled()) return;
            layer->prepare(ctx);
        }
        combine();
    }

    void completePreparation(TaskContext& ctx) override {
        for (auto& layer : layers_)
            if (!ctx.isCancelled()) layer->completePreparation(ctx);
    }

    double deferredPreparationSeconds() const override {
        double s = 0;
        for (const auto& layer : layers_) s += layer->deferredPreparationSeconds();
        return s;
    }

    void renderPass(TaskContext& ctx, int pass) override {
        for (auto& layer : layers_) {
            layer->renderPass(ctx, pass);
            if (ctx.isCancelled()) return;
        }
        combine();
    }

    const Film& film() const override { return combined_; }

    void rewriteFilms(const std::function<void(Film&)>& rewrite) override {
        for (auto& layer : layers_) layer->rewriteFilms(rewrite);
        combine();
    }

    std::map<std::string, std::string> diagnostics() const override {
        std::map<std::string, std::string> d = layers_.front()->diagnostics();
        d["light_layers"] = std::to_string(groups_.size());
        return d;
    }

    void addImageLayers(Image& image) const override {
        for (size_t g = 0; g < groups_.size(); ++g) {
            const Image layer = layers_[g]->film().image();
            for (int c = 0; c < 3; ++c) {
                std::vector<float>& channel = image.channels[lightLayerChannel(groups_[g], "RGB"[c])];
                channel.resize(layer.pixelCount());
                for (size_t i = 0; i < layer.pixelCount(); ++i) channel[i] = layer.pixels[i][c];
            }
        }
    }

private:
    void combine() {
        std::vector<const Film*> films;
        for (const auto& layer : layers_) films.push_back(&layer->film());
        combined_ = Film::sum(films);
    }

    std::vector<LightGroup> groups_;
    std::vector<std::unique_ptr<Backend>> layers_;
    Film combined_;
};

}  // namespace

std::unique_ptr<Backend> makeLayeredBackend(BackendFactory base, SceneSnapshot scene,
                                                       const RenderSettings& settings) {
    return std::make_unique<LayeredBackend>(base, std::move(scene), settings);
}

}  // namespace lucerna
