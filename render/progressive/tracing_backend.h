#pragma once
// The common part of the backends that trace rays on the CPU (path, bdpt, ir, mir, mlt and
// cmlt): the scene snapshot and settings they are made with, and what every one of them prepares
// first: the render scene (Embree's BVH, light tables) at the requested resolution or for the
// requested sensors, counting rays into the settings' recorder, and a film of its size.
// PassFunctionBackend: such a backend made of one pass function.

#include "render/backend/backend.h"
#include "render/backend/backend_options.h"
#include "render/backend/film.h"
#include "render/trace/render_scene.h"
#include "render/trace/render_scene_cache.h"

#include <memory>
#include <optional>
#include <vector>

namespace lucerna {

class TracingBackend : public Backend {
public:
    const Film& film() const override { return *film_; }
    void rewriteFilms(const std::function<void(Film&)>& rewrite) override { rewrite(*film_); }

protected:
    // Lights switched off are left out here, so that no tracing backend ever sees them.
    // lightSelection: how next-event estimation chooses lights; by default the option
    // light_sampler (backend_options.h). portalsByDefault: daylight_portals where not given
    // (README, "Daylight in the renderers", says why it is off but for mir).
    TracingBackend(SceneSnapshot scene, const RenderSettings& settings,
                   std::optional<LightSelection> lightSelection = std::nullopt, bool portalsByDefault = false)
        : snapshot_(sceneAsRendered(std::move(scene))), settings_(settings),
          lightSelection_(lightSelection ? *lightSelection : lightSelectionOption(settings)),
          daylightPortals_(daylightPortalsOption(settings, portalsByDefault)) {}

    // Builds scene_ and film_; a backend that prepares more calls it first.
    void prepareSceneAndFilm() {
        const auto build = [&] {
            auto scene = std::make_shared<RenderScene>(snapshot_, settings_.width, settings_.height,
                                                       settings_.sensor.get(), lightSelection_, daylightPortals_);
            scene->setRayRecorder(settings_.rayRecorder);
            return std::shared_ptr<const RenderScene>(std::move(scene));
        };
        scene_ = settings_.sharedScenes ? settings_.sharedScenes->get(lightSelection_, daylightPortals_, build) : build();
        film_ = std::make_unique<Film>(scene_->camera().width(), scene_->camera().height());
    }

    SceneSnapshot snapshot_;
    RenderSettings settings_;
    // How next-event estimation chooses lights (option light_sampler).
    LightSelection lightSelection_;
    bool daylightPortals_;  // option daylight_portals
    std::shared_ptr<const RenderScene> scene_;
    std::unique_ptr<Film> film_;
};

// A tracing backend whose pass is one function of the render scene and its own settings (path,
// bdpt): it prepares the scene and film alone, and renderPass(ctx, pass) is
// pass(scene, settings, seed, pass, film, ctx), the settings read by fromOptions.
template <class Settings>
class PassFunctionBackend : public TracingBackend {
public:
    using FromOptions = Settings (*)(const RenderSettings&);
    using Pass = void (*)(const RenderScene&, const Settings&, uint64_t seed, int pass, Film&, TaskContext&);

    PassFunctionBackend(SceneSnapshot scene, const RenderSettings& settings, FromOptions fromOptions, Pass pass,
                        std::optional<LightSelection> lightSelection = std::nullopt)
        : TracingBackend(std::move(scene), settings, lightSelection), passSettings_(fromOptions(settings)),
          pass_(pass) {}

    void prepare(TaskContext&) override { prepareSceneAndFilm(); }
    void renderPass(TaskContext& ctx, int pass) override {
        pass_(*scene_, passSettings_, settings_.seed, pass, *film_, ctx);
    }

private:
    Settings passSettings_;
    Pass pass_;
};

}  // namespace lucerna
