#pragma once
// The progressive backends and the explicit table that names them (Tungsten-style). A backend
// owns its film; the driver (progressive_render.h) schedules its passes and publishes frames.

#include "core/image.h"
#include "core/scene.h"
#include "core/task_system.h"
#include "render/progressive/film.h"
#include "render/trace/sensor.h"

#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace lucerna {

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
};

class ProgressiveBackend {
public:
    virtual ~ProgressiveBackend() = default;

    // Builds what rendering needs (acceleration structure, light tables). Not part of a --time
    // budget. May throw std::runtime_error.
    virtual void prepare(TaskContext& ctx) = 0;
    // Adds one pass to the film: one sample per pixel's worth of work. Pass p goes to half p % 2.
    // Returns without finishing the pass when ctx is cancelled (the film is then abandoned).
    virtual void renderPass(TaskContext& ctx, int pass) = 0;
    virtual const Film& film() const = 0;
    // Figures for the EXR header and the convergence panel (name -> value).
    virtual std::map<std::string, std::string> diagnostics() const { return {}; }
    // Adds named channels of the film's combined image to `image` (per-light layers), if any.
    virtual void addImageLayers(Image& image) const { (void)image; }
};

using BackendFactory = std::unique_ptr<ProgressiveBackend> (*)(SceneSnapshot, const RenderSettings&);

struct BackendInfo {
    std::string_view name;
    std::string_view summary;
    BackendFactory make;
    std::span<const std::string_view> options;  // every option key its settings read
};

// Every backend that exists, in the order the UI lists them.
std::span<const BackendInfo> backendTable();
// nullptr when no backend has that name.
const BackendInfo* findBackend(std::string_view name);
// Throws std::invalid_argument, one line naming the key and the options there are, when
// `options` holds a key that none of `backends` reads (a mistyped option would otherwise be
// ignored and the render made with the default).
void requireKnownOptions(const std::map<std::string, std::string>& options, std::span<const BackendInfo* const> backends);

// What `--backend auto` picks for a scene, and why, in one line.
struct AutoChoice {
    std::string backend;
    std::string reason;
};
AutoChoice chooseAutoBackend(const Scene& scene);

}  // namespace lucerna
