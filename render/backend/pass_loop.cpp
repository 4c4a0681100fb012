#include "render/backend/pass_loop.h"

#include "core/number_format.h"
#include "render/trace/render_scene.h"
#include "render/trace/surface_layers.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <thread>

namespace lucerna {

RenderFrame makeRenderFrame(const Backend& backend, std::string_view backendName,
                            const RenderSettings& settings, double seconds, int passes) {
    RenderFrame f;
    f.image = backend.film().image();
    f.seconds = seconds;
    f.samplesPerPixel = backend.film().samplesPerPixel();
    f.passes = passes;
    f.estimatedRelmse = backend.estimatedRelmse();
    f.image.attributes["lucerna:backend"] = std::string(backendName);
    f.image.attributes["lucerna:spp"] = formatNumber(f.samplesPerPixel);
    f.image.attributes["lucerna:seconds"] = formatNumber(f.seconds);
    f.image.attributes["lucerna:seed"] = std::to_string(settings.seed);
    if (std::isfinite(f.estimatedRelmse)) f.image.attributes["lucerna:estimated_relmse"] = formatNumber(f.estimatedRelmse, 4);
    for (const auto& [k, v] : backend.diagnostics()) f.image.attributes["lucerna:" + k] = v;
    backend.addImageLayers(f.image);
    return f;
}

RenderFrame runPasses(Backend& backend, std::string_view backendName, const RenderSettings& settings,
                           TaskContext& ctx, Latest<RenderFrame>* latest, const PassLoopOptions& options) {
    using Clock = std::chrono::steady_clock;
    const int renderPasses =
        options.openEnded ? 0 : (settings.spp > 0 ? settings.spp : (settings.seconds > 0 ? 0 : 64));
    const int shareCount = std::max(1, options.shareCount), shareIndex = std::clamp(options.shareIndex, 0, shareCount - 1);
    // This process's passes: indices shareIndex, shareIndex + shareCount, ... below renderPasses.
    const int targetPasses =
        renderPasses > 0 ? std::max(0, (renderPasses - shareIndex + shareCount - 1) / shareCount) : 0;
    const bool countedPasses = renderPasses > 0;  // else the time budget decides
    const double budget = settings.seconds;
    const auto start = Clock::now();
    double heldSeconds = 0;
    // Held time and deferred preparation are not the passes'.
    const auto elapsed = [&] {
        return std::chrono::duration<double>(Clock::now() - start).count() - heldSeconds -
               backend.deferredPreparationSeconds();
    };

    std::optional<SurfaceLayers> surfaces;
    const auto makeFrame = [&](int passes) {
        RenderFrame frame = makeRenderFrame(backend, backendName, settings, elapsed(), passes);
        if (options.albedoScene && passes >= 4) {
            if (!surfaces)
                surfaces = traceSurfaceLayers(
                    RenderScene(options.albedoScene, backend.film().width(), backend.film().height()));
            addSurfaceLayers(frame.image, *surfaces, kAlbedoLayer);
        }
        return frame;
    };

    int passes = 0;
    double lastPublish = 0;
    while (!ctx.isCancelled()) {
        if (options.hold && options.hold()) {
            const auto t0 = Clock::now();
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            heldSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
            continue;
        }
        if (!options.openEnded) {
            if (options.finishEarly && options.finishEarly()) break;
            if (countedPasses && passes >= targetPasses) break;
            if (!countedPasses && elapsed() >= budget) break;
        }
        backend.renderPass(ctx, options.globalPassIndices ? shareIndex + passes * shareCount : passes);
        if (ctx.isCancelled()) break;
        ++passes;
        if (options.afterPass) options.afterPass(passes);
        const double t = elapsed();
        if (!options.openEnded) {
            double fraction = countedPasses ? double(passes) / std::max(1, targetPasses) : t / budget;
            if (countedPasses && budget > 0) fraction = std::max(fraction, t / budget);
            ctx.setProgress(std::min(1.0, fraction));
            if (countedPasses && budget > 0 && t >= budget) break;  // both given: whichever comes first
        }
        if (latest && (passes <= options.eagerPasses ||
                       t - lastPublish >= std::max(options.publishSeconds, options.publishShare * t))) {
            latest->publish(std::make_shared<const RenderFrame>(makeFrame(passes)));
            lastPublish = t;
        }
    }
    if (options.openEnded) return {};
    RenderFrame final = makeFrame(passes);
    if (latest) latest->publish(std::make_shared<const RenderFrame>(final));
    return final;
}

}  // namespace lucerna
