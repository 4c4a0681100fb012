#include "render/preview/preview.h"

#include "render/trace/rng.h"

#include <numbers>

namespace lucerna {

std::vector<float> previewIlluminanceLayer(SceneSnapshot scene, int width, int height,
                                           const PreviewSettings& settings, int frames, uint64_t seed) {
    Preview preview;
    preview.setSettings(settings);
    preview.setScene(std::move(scene), width, height);
    preview.setWhiteReceivers(true);
    std::vector<double> sum;
    for (int f = 0; f < frames; ++f) {
        const uint64_t frameSeed = hashSeed(seed, uint64_t(f), 0x1ec5);
        preview.regenerate(frameSeed);
        Rng rng(frameSeed, 0x717e7ULL);
        const V2f jitter = rng.next2D();
        const Image frame = preview.render(jitter.x, jitter.y);
        sum.resize(frame.pixelCount(), 0.0);
        for (size_t i = 0; i < sum.size(); ++i)
            if (isFinite(frame.pixels[i])) sum[i] += double(luminance(frame.pixels[i]));
    }
    std::vector<float> lux(sum.size());
    const double scale = kLumensPerWatt * std::numbers::pi / std::max(1, frames);
    for (size_t i = 0; i < sum.size(); ++i) lux[i] = float(sum[i] * scale);
    return lux;
}

}  // namespace lucerna
