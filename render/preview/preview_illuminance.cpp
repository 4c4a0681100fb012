#include "render/preview/preview_illuminance.h"

#include "render/preview/frame_accumulator.h"
#include "render/trace/rng.h"

#include <numbers>

namespace lucerna {

std::vector<float> previewIlluminanceLayer(SceneSnapshot scene, int width, int height,
                                           const PreviewSettings& settings, int frames, uint64_t seed) {
    Preview preview;
    preview.setSettings(settings);
    preview.setScene(std::move(scene), width, height);
    preview.setWhiteReceivers(true);
    FrameAccumulator sum;
    for (int f = 0; f < frames; ++f) {
        const uint64_t frameSeed = hashSeed(seed, uint64_t(f), 0x1ec5);
        sum.add(drawJitteredFrame(preview, frameSeed, uniformJitter(frameSeed)));
    }
    const Image mean = sum.mean();
    std::vector<float> lux(mean.pixelCount());
    for (size_t i = 0; i < lux.size(); ++i)
        lux[i] = float(kLumensPerWatt * std::numbers::pi * double(luminance(mean.pixels[i])));
    return lux;
}

}  // namespace lucerna
