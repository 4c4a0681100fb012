#pragma once
// Rendering from tests: a scene from JSON text, a backend by name, a fixed amount of work.

#include "core/scene/scene_io.h"
#include "core/task_system.h"
#include "render/backend/pass_loop.h"
#include "render/engine/backend_table.h"

#include <stdexcept>
#include <string>

namespace lucerna::test {

inline SceneSnapshot sceneFromJson(const std::string& json, const std::string& name = "test.json") {
    return std::make_shared<const Scene>(parseScene(json, name));
}

// Prepares `backend` and runs it for the work `settings` give, on `threads` threads (0: all).
inline RenderFrame runBackend(Backend& backend, const std::string& backendName,
                              const RenderSettings& settings, int threads = 0) {
    TaskSystem tasks(threads);
    RenderFrame frame;
    auto job = tasks.submit([&](TaskContext& ctx) {
        backend.prepare(ctx);
        frame = runPasses(backend, backendName, settings, ctx);
    });
    job->wait();
    job->rethrowIfFailed();
    return frame;
}

inline RenderFrame renderFrame(const std::string& backendName, const SceneSnapshot& scene, const RenderSettings& settings,
                               int threads = 0) {
    const BackendInfo* info = findBackend(backendName);
    if (!info) throw std::invalid_argument("no backend " + backendName);
    auto backend = info->make(scene, settings);
    return runBackend(*backend, backendName, settings, threads);
}

inline Image render(const std::string& backendName, const SceneSnapshot& scene, int spp, uint64_t seed = 1,
                    int width = 0, int height = 0) {
    RenderSettings s;
    s.spp = spp;
    s.seed = seed;
    s.width = width;
    s.height = height;
    return renderFrame(backendName, scene, s).image;
}

// The mean over an image's pixels and channels.
inline double channelMean(const Image& img) {
    double s = 0;
    for (const Rgb& p : img.pixels) s += double(p.x) + p.y + p.z;
    return s / (3.0 * double(img.pixels.size()));
}

}  // namespace lucerna::test
