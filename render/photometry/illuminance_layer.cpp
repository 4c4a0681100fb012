#include "render/photometry/illuminance_layer.h"

#include "render/backend/pooled_films.h"
#include "render/photometry/irradiance_estimator.h"
#include "render/photometry/sensor_render.h"
#include "render/preview/headless_backend.h"
#include "render/preview/preview_illuminance.h"
#include "render/vpl/instant_radiosity.h"

#include <algorithm>
#include <atomic>
#include <optional>

namespace lucerna {

namespace {

constexpr int kMaxSpecularDepth = 16;

// The surface a camera ray ends on, as a sensor on the side the ray arrives from.
std::optional<IrradianceSensor> surfaceSeen(const RenderScene& scene, const Ray& ray, Rng& rng) {
    const CameraVertex cv = traceCameraVertex(scene, ray, rng, kMaxSpecularDepth);
    if (!cv.found) return std::nullopt;
    const SurfacePoint& p = cv.receiver.x;
    return IrradianceSensor{p.p, p.ng.dot(cv.receiver.wo) < 0.0f ? -p.ng : p.ng};
}

std::vector<float> byEstimator(const RenderScene& scene, GridMethod method, int samplesPerPixel, uint64_t seed,
                               TaskContext& ctx, RowShare share) {
    const Sensor& camera = scene.camera();
    const int width = camera.width(), height = camera.height();
    std::vector<float> lux(size_t(width) * size_t(height), 0.0f);
    const IrradianceEstimator estimator(scene);
    std::vector<VplSet> vpls;
    if (method == GridMethod::Vpl)
        for (int s = 0; s < samplesPerPixel && !ctx.isCancelled(); ++s)
            vpls.push_back(generateVpls(scene, 16, hashSeed(seed, uint64_t(s), 0x9d1)));
    std::atomic<int> rowsDone{0};
    ctx.parallelFor(0, height, [&](int y) {
        if (!share.owns(y)) return;
        for (int x = 0; x < width; ++x) {
            Rng rng(hashSeed(seed, 0x11c), uint64_t(y) * uint64_t(width) + uint64_t(x));
            double sum = 0;
            for (int s = 0; s < samplesPerPixel; ++s) {
                const V2f jitter = rng.next2D();
                const auto sensor = surfaceSeen(scene, camera.ray(float(x) + jitter.x, float(y) + jitter.y), rng);
                if (!sensor) continue;
                const Rgb E = method == GridMethod::Vpl ? estimator.sampleVpl(*sensor, rng, vpls[size_t(s)])
                                                        : estimator.samplePath(*sensor, rng);
                if (isFinite(E)) sum += kLumensPerWatt * double(luminance(E));
            }
            lux[size_t(y) * size_t(width) + size_t(x)] = float(sum / samplesPerPixel);
        }
        ctx.setProgress(std::min(1.0, double(++rowsDone) * share.count / height));
    });
    return lux;
}

std::vector<float> byBackend(const RenderScene& scene, GridMethod method, int passes, uint64_t seed,
                             TaskContext& ctx, const std::map<std::string, std::string>& options, RowShare share) {
    const Sensor& camera = scene.camera();
    const int width = camera.width(), height = camera.height();
    std::vector<float> lux(size_t(width) * size_t(height), 0.0f);
    std::vector<IrradianceSensor> sensors;
    std::vector<size_t> pixelOf;  // the pixel of each sensor
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width && share.owns(y); ++x) {
            const size_t pixel = size_t(y) * size_t(width) + size_t(x);
            Rng rng(hashSeed(seed, 0x11d), pixel);
            if (const auto s = surfaceSeen(scene, camera.ray(float(x) + 0.5f, float(y) + 0.5f), rng)) {
                sensors.push_back(*s);
                pixelOf.push_back(pixel);
            }
        }
    if (sensors.empty()) return lux;
    SensorRender render(scene, gridMethodName(method), sensors, 1, processSeed(seed, share.index), options);
    render.prepare(ctx);
    for (int pass = 0; pass < passes && !ctx.isCancelled(); ++pass) {
        render.renderPass(ctx, pass);
        ctx.setProgress(double(pass + 1) / passes);
    }
    const std::vector<double> values = render.lux();
    for (size_t i = 0; i < values.size(); ++i) lux[pixelOf[i]] = float(values[i]);
    return lux;
}

}  // namespace

std::vector<float> traceIlluminanceLayer(const RenderScene& scene, GridMethod method, int samplesPerPixel,
                                         uint64_t seed, TaskContext& ctx,
                                         const std::map<std::string, std::string>& options, RowShare share) {
    share.count = std::max(1, share.count);
    if (method == GridMethod::Path || method == GridMethod::Vpl)
        return byEstimator(scene, method, samplesPerPixel, seed, ctx, share);
    if (method == GridMethod::Preview) {
        if (share.index != 0) return std::vector<float>(size_t(scene.camera().width()) * scene.camera().height(), 0.0f);
        RenderSettings settings;
        settings.seed = seed;
        settings.options = options;
        return previewIlluminanceLayer(scene.snapshot(), scene.camera().width(), scene.camera().height(),
                                       previewSettingsFromOptions(settings), samplesPerPixel, seed);
    }
    return byBackend(scene, method, samplesPerPixel, seed, ctx, options, share);
}

}  // namespace lucerna
