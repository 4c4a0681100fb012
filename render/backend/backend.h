#pragma once
// The interface every backend implements (the progressive ones and the headless preview). A
// backend owns its film; the pass loop (pass_loop.h) schedules its passes and publishes frames.
// The table that names the backends is a layer above (render/engine/backend_table.h).

#include "core/image/image.h"
#include "core/scene/scene.h"
#include "core/task_system.h"
#include "render/backend/film.h"
#include "render/trace/sensor.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lucerna {

class RenderSceneCache;

struct RenderSettings {
    int spp = 0;            // work equal to this many samples per pixel (0: not given)
    double seconds = 0.0;   // wall-clock budget after prepare() (0: not given)
    uint64_t seed = 0;
    int width = 0, height = 0;  // override the camera's resolution (0: keep)
    // Irradiance sensors to measure instead of the camera (calculation grids, the illuminance
    // layer); nullptr: the camera. Backends that cannot measure them (the preview) refuse in
    // prepare().
    std::shared_ptr<const Sensor> sensor;
    // Benchmarks: counts (or records) every ray the backend traces, prepare() included; the
    // preview traces none. Must outlive the backend.
    RayRecorder* rayRecorder = nullptr;
    // Backend-specific options, "name=value" from the command line or the UI.
    std::map<std::string, std::string> options;
    // Several backends of one render (auto's candidates, render/engine/measured_auto/): the
    // tracing backends take their render scene from here, one per way of sampling lights, so
    // that they share one BVH and one set of light tables. nullptr: each builds its own.
    std::shared_ptr<RenderSceneCache> sharedScenes;
    // The window: a backend of several methods (auto) prepares each just before its first pass,
    // so that the first frame comes after one method's preparation. Otherwise all are prepared
    // in prepare(), so that `seconds` (and a benchmark's clock) counts passes only, as for a
    // single method.
    bool firstFrameSoon = false;
    // The caller may stop a backend after a pass or two (auto's pilots) and calls
    // Backend::completePreparation() before it goes on: preparation only a longer run needs may
    // wait until then (mlt's and cmlt's bootstrap; the option bootstrap_first_per_pixel says how
    // much comes first).
    bool deferPreparation = false;
};

class Backend {
public:
    virtual ~Backend() = default;

    // Builds what rendering needs (acceleration structure, light tables). Not part of a --time
    // budget. May throw std::runtime_error.
    virtual void prepare(TaskContext& ctx) = 0;
    // Work that prepare() left for the passes to come, done now: a Metropolis backend's bootstrap
    // past its first pass's samples (mlt's bootstrap_first_per_pixel). A backend does it itself
    // when a pass needs it; a caller that counts the passes' cost (auto) asks for it first, so
    // that it is preparation there too. Not part of a --time budget.
    virtual void completePreparation(TaskContext& ctx) { (void)ctx; }
    // The seconds that work took so far, in completePreparation() or in passes: the pass loop
    // leaves them out of a --time budget, as it leaves prepare() out.
    virtual double deferredPreparationSeconds() const { return 0; }
    // Adds one pass to the film: one sample per pixel's worth of work. Pass p goes to half p % 2.
    // Returns without finishing the pass when ctx is cancelled (the film is then abandoned).
    virtual void renderPass(TaskContext& ctx, int pass) = 0;
    virtual const Film& film() const = 0;
    // The relmse of film()'s image estimated without a reference: by default from the film's two
    // halves (Film::estimatedRelmse); a backend whose halves are not two equal estimates (auto)
    // says its own.
    virtual double estimatedRelmse() const { return film().estimatedRelmse(); }
    // Figures for the EXR header and the convergence panel (name -> value).
    virtual std::map<std::string, std::string> diagnostics() const { return {}; }
    // Adds named channels of the film's combined image to `image` (per-light layers), if any.
    virtual void addImageLayers(Image& image) const { (void)image; }

    // Distributed renders (render/backend/pooled_films.h), once the passes are done: calls
    // `rewrite` on each film the frame is made of, in a fixed order (the film, or each light
    // layer's), then remakes what derives from them (a layered backend's sum). With the films
    // pooled from every process, film(), diagnostics() and addImageLayers() show the whole run
    // (diagnostics that count a backend's own chains still count this process's).
    virtual void rewriteFilms(const std::function<void(Film&)>& rewrite) = 0;
};

// Makes a backend for a scene; the backend prepares nothing until prepare().
using BackendFactory = std::unique_ptr<Backend> (*)(SceneSnapshot, const RenderSettings&);

}  // namespace lucerna
