#include "render/progressive/progressive_render.h"

#include <chrono>
#include <cstdio>

namespace lucerna {

std::string formatNumber(double v, int significantDigits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", significantDigits, v);
    return buf;
}

RenderFrame makeRenderFrame(const ProgressiveBackend& backend, std::string_view backendName,
                            const RenderSettings& settings, double seconds, int passes) {
    RenderFrame f;
    f.image = backend.film().image();
    f.seconds = seconds;
    f.samplesPerPixel = backend.film().samplesPerPixel();
    f.passes = passes;
    f.estimatedRelmse = backend.film().estimatedRelmse();
    f.image.attributes["lucerna:backend"] = std::string(backendName);
    f.image.attributes["lucerna:spp"] = formatNumber(f.samplesPerPixel);
    f.image.attributes["lucerna:seconds"] = formatNumber(f.seconds);
    f.image.attributes["lucerna:seed"] = std::to_string(settings.seed);
    for (const auto& [k, v] : backend.diagnostics()) f.image.attributes["lucerna:" + k] = v;
    backend.addImageLayers(f.image);
    return f;
}

RenderFrame runProgressive(ProgressiveBackend& backend, std::string_view backendName, const RenderSettings& settings,
                           TaskContext& ctx, Latest<RenderFrame>* latest, double publishSeconds) {
    using Clock = std::chrono::steady_clock;
    const int targetPasses = settings.spp > 0 ? settings.spp : (settings.seconds > 0 ? 0 : 64);
    const double budget = settings.seconds;
    const auto start = Clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

    const auto makeFrame = [&](int passes) { return makeRenderFrame(backend, backendName, settings, elapsed(), passes); };

    int passes = 0;
    double lastPublish = 0;
    while (!ctx.isCancelled()) {
        if (targetPasses > 0 && passes >= targetPasses) break;
        if (targetPasses == 0 && elapsed() >= budget) break;
        backend.renderPass(ctx, passes);
        if (ctx.isCancelled()) break;
        ++passes;
        const double t = elapsed();
        double fraction = targetPasses > 0 ? double(passes) / targetPasses : t / budget;
        if (targetPasses > 0 && budget > 0) fraction = std::max(fraction, t / budget);
        ctx.setProgress(std::min(1.0, fraction));
        if (targetPasses > 0 && budget > 0 && t >= budget) break;  // both given: whichever comes first
        if (latest && t - lastPublish >= publishSeconds) {
            latest->publish(std::make_shared<const RenderFrame>(makeFrame(passes)));
            lastPublish = t;
        }
    }
    RenderFrame final = makeFrame(passes);
    if (latest) latest->publish(std::make_shared<const RenderFrame>(final));
    return final;
}

}  // namespace lucerna
