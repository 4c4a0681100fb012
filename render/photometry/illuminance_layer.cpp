#include "render/photometry/illuminance_layer.h"

#include "render/photometry/irradiance_estimator.h"

#include <atomic>

namespace lucerna {

std::vector<float> traceIlluminanceLayer(const RenderScene& scene, int samplesPerPixel, uint64_t seed,
                                         TaskContext& ctx) {
    const PinholeCamera& camera = scene.camera();
    const int width = camera.width(), height = camera.height();
    std::vector<float> lux(size_t(width) * size_t(height), 0.0f);
    const IrradianceEstimator estimator(scene);
    constexpr int kMaxSpecularDepth = 16;
    std::atomic<int> rowsDone{0};
    ctx.parallelFor(0, height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            Rng rng(hashSeed(seed, 0x11c), uint64_t(y) * uint64_t(width) + uint64_t(x));
            double sum = 0;
            for (int s = 0; s < samplesPerPixel; ++s) {
                const V2f jitter = rng.next2D();
                const Ray ray = camera.ray(float(x) + jitter.x, float(y) + jitter.y);
                const CameraVertex cv = traceCameraVertex(scene, ray, rng, kMaxSpecularDepth);
                if (!cv.found) continue;
                const SurfacePoint& p = cv.receiver.x;
                // Two-sided surfaces are lit on the side the camera path arrives from.
                const V3f n = p.ng.dot(cv.receiver.wo) < 0.0f ? -p.ng : p.ng;
                const Rgb E = estimator.samplePath(IrradianceSensor{p.p, n}, rng);
                if (isFinite(E)) sum += kLumensPerWatt * double(luminance(E));
            }
            lux[size_t(y) * size_t(width) + size_t(x)] = float(sum / samplesPerPixel);
        }
        ctx.setProgress(double(++rowsDone) / height);
    });
    return lux;
}

}  // namespace lucerna
