#include "render/preview/headless_backend.h"

#include "render/backend/backend_options.h"
#include "render/preview/frame_accumulator.h"
#include "render/trace/rng.h"

#include <cstdio>
#include <stdexcept>

namespace lucerna {

PreviewSettings previewSettingsFromOptions(const RenderSettings& settings) {
    PreviewSettings p;
    p.seed = settings.seed;
    readOption(settings, "vpls", p.vplCount, 0);
    readOption(settings, "clamp", p.clampDistance, 0.0, std::numeric_limits<float>::max());
    readOption(settings, "area_samples", p.areaLightSamples, 0);
    readOption(settings, "unroll", p.maxUnrolledVpls, 0);
    readOption(settings, "shaded_lights", p.lightsShadedInFull, 0);
    readOption(settings, "proxy_triangles", p.shadowProxyTriangles, 0);
    readOption(settings, "sky_samples", p.skySamples, 0);
    readOption(settings, "sky_shadow_size", p.skyShadowSize, 1, 16384);
    for (const auto& option : settings.options) {
        const std::string& key = option.first;  // not a structured binding: clang 14 cannot capture one
        const std::string& value = option.second;
        const auto bad = [&](const char* what) {
            return std::invalid_argument("option " + key + " must be " + what + " (got '" + value + "')");
        };
        if (key == "pattern") {
            int n = 0, m = 0;
            char x = 0, extra = 0;
            if (std::sscanf(value.c_str(), "%d%c%d%c", &n, &x, &m, &extra) != 3 || x != 'x' || n < 1 || m < 1)
                throw bad("NxM with positive N and M");
            p.patternX = n;
            p.patternY = m;
        } else if (key == "visibility" || key == "blur") {
            if (value != "0" && value != "1") throw bad("0 or 1");
            (key == "blur" ? p.blur : p.visibility) = value == "1";
        } else if (key == "split") {
            if (value != "fused" && value != "one" && value != "two") throw bad("fused, one or two");
            p.split = value == "two" ? SplitMode::TwoPass : value == "one" ? SplitMode::OnePass : SplitMode::Fused;
        } else if (key == "vpl_source") {
            if (value != "ir" && value != "mir") throw bad("ir or mir");
            p.vplSource = value == "mir" ? VplSource::Metropolis : VplSource::InstantRadiosity;
            p.metropolisUnderDaylight = value == "mir";  // asked for by name: ir under daylight too
        }
        // Other keys belong to other backends (the CLI passes every option to every backend).
    }
    return p;
}

namespace {

class PreviewBackend final : public Backend {
public:
    PreviewBackend(SceneSnapshot scene, const RenderSettings& settings)
        : snapshot_(std::move(scene)), settings_(settings), previewSettings_(previewSettingsFromOptions(settings)) {}

    void prepare(TaskContext&) override {
        if (settings_.sensor)
            throw std::runtime_error("the preview renders only through the camera, not irradiance sensors");
        preview_ = std::make_unique<Preview>();
        preview_->setSettings(previewSettings_);
        preview_->setScene(snapshot_, settings_.width, settings_.height);
        const Image probe = preview_->render();  // sizes the film and compiles everything up front
        frames_.restart(probe.width, probe.height);
    }

    void renderPass(TaskContext& ctx, int pass) override {
        if (ctx.isCancelled()) return;
        const uint64_t passSeed = hashSeed(settings_.seed, uint64_t(pass));
        frames_.add(drawJitteredFrame(*preview_, passSeed, uniformJitter(passSeed)), pass % 2);
        for (const auto& [name, ms] : {std::pair{"gbuffer", preview_->timings().gbuffer},
                                       {"shading", preview_->timings().shading}, {"total", preview_->timings().total}})
            lastTimings_[std::string("preview:ms_") + name] = std::to_string(ms);
    }

    const Film& film() const override { return frames_.film(); }
    void rewriteFilms(const std::function<void(Film&)>& rewrite) override { rewrite(frames_.film()); }

    std::map<std::string, std::string> diagnostics() const override {
        auto d = lastTimings_;
        d["preview:renderer"] = preview_ ? preview_->context().renderer() : "";
        d["preview:degradation"] = preview_ ? preview_->degradation() : "";
        d["preview:vpls"] = std::to_string(previewSettings_.vplCount);
        d["preview:vpl_source"] = preview_ && preview_->usesMetropolis() ? "mir" : "ir";
        d["preview:pattern"] = std::to_string(previewSettings_.patternX) + "x" + std::to_string(previewSettings_.patternY);
        return d;
    }

private:
    SceneSnapshot snapshot_;
    RenderSettings settings_;
    PreviewSettings previewSettings_;
    std::unique_ptr<Preview> preview_;
    FrameAccumulator frames_;
    std::map<std::string, std::string> lastTimings_;
};

}  // namespace

std::unique_ptr<Backend> makePreviewBackend(SceneSnapshot scene, const RenderSettings& settings) {
    return std::make_unique<PreviewBackend>(std::move(scene), settings);
}

}  // namespace lucerna
