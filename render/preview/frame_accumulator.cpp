#include "render/preview/frame_accumulator.h"

#include "render/trace/rng.h"

#include <cmath>

namespace lucerna {

V2f uniformJitter(uint64_t frameSeed) {
    Rng rng(frameSeed, 0x717e7ULL);
    return rng.next2D();
}

V2f sequenceJitter(int k) {
    constexpr double g = 1.32471795724474602596;  // the plastic number
    const auto frac = [](double x) { return x - std::floor(x); };
    return V2f(float(frac(0.5 + k / g)), float(frac(0.5 + k / (g * g))));
}

Image drawJitteredFrame(Preview& preview, uint64_t seed, V2f jitter, FrameRenewal renewal) {
    if (renewal == FrameRenewal::FreshSet) preview.regenerate(seed);
    else preview.redeal(seed);
    return preview.render(jitter.x, jitter.y);
}

void FrameAccumulator::restart(int width, int height) {
    film_ = Film(width, height);
    channels_.clear();
    attributes_.clear();
    frames_ = 0;
}

void FrameAccumulator::add(const Image& frame, int half) {
    if (frame.width != film_.width() || frame.height != film_.height()) restart(frame.width, frame.height);
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            const Rgb& L = frame.at(x, y);
            film_.addSample(half, x, y, isFinite(L) ? L : Rgb(0, 0, 0));
        }
    film_.finishPass(half);
    if (frames_ == 0) attributes_ = frame.attributes;
    for (const auto& [name, values] : frame.channels) {
        if (frames_ == 0) channels_[name].assign(values.size(), 0.0);
        const auto it = channels_.find(name);
        if (it == channels_.end() || it->second.size() != values.size()) continue;
        for (size_t i = 0; i < values.size(); ++i)
            if (std::isfinite(values[i])) it->second[i] += values[i];
    }
    ++frames_;
}

Image FrameAccumulator::mean() const {
    Image m = film_.image();
    m.attributes = attributes_;
    for (const auto& [name, sum] : channels_) {
        std::vector<float>& layer = m.channels[name];
        layer.resize(sum.size());
        for (size_t i = 0; i < sum.size(); ++i) layer[i] = float(sum[i] / std::max(frames_, 1));
    }
    return m;
}

}  // namespace lucerna
