#include "render/progressive/cmlt/lens_mutation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lucerna {

namespace {
// Wrapped into [0, size).
float wrap(float v, float size) {
    v = std::fmod(v, size);
    if (v < 0.0f) v += size;
    return v < size ? v : 0.0f;
}
}  // namespace

V2f perturbRaster(const V2f& x, float sigmaPixels, float width, float height, Rng& rng) {
    // Box-Muller: two independent standard normal numbers.
    const double r = std::sqrt(-2.0 * std::log(1.0 - rng.nextDouble()));
    const double phi = 2.0 * std::numbers::pi * rng.nextDouble();
    return V2f(wrap(x.x + sigmaPixels * float(r * std::cos(phi)), width),
               wrap(x.y + sigmaPixels * float(r * std::sin(phi)), height));
}

LensMove chooseLensMove(std::span<const double> candidateF, double currentF, Rng& rng) {
    LensMove m;
    const int p = int(candidateF.size());
    m.candidate = std::min(p - 1, int(rng.nextDouble() * p));
    m.accepted = rng.nextDouble() < std::min(1.0, candidateF[size_t(m.candidate)] / currentF);
    return m;
}

}  // namespace lucerna
