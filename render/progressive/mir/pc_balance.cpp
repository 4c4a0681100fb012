#include "render/progressive/mir/pc_balance.h"

#include "render/backend/film.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lucerna {

void measureImageTerms(const Film& rest, const Film& vplLight, double pc, PcBalance& b) {
    Film vpl = vplLight;
    vpl.setHalfScale(0, pc);
    vpl.setHalfScale(1, pc);
    const std::array<const Film*, 2> films{&rest, &vpl};
    const Film all = Film::sum(films);
    const Image image = all.image(), vplImage = vpl.image();
    // s: a relative error e of Pc moves a pixel by e V, which SPEC's relmse counts as
    // e^2 V^2 / (I^2 + 0.01), with the image I standing in for the reference.
    double s = 0;
    for (size_t p = 0; p < image.pixels.size(); ++p)
        for (int c = 0; c < 3; ++c) {
            const double v = vplImage.pixels[p][c], i = image.pixels[p][c];
            s += v * v / (i * i + 0.01);
        }
    b.sensitivity = s / (3.0 * double(std::max<size_t>(1, image.pixels.size())));
    b.passRelmse = all.estimatedRelmse() * all.samplesPerPixel();
}

int balancedPcSamples(const PcBalance& b, int least, int most, int fallback) {
    const double product = b.sensitivity * b.sampleRelativeVariance * b.passRays;
    const double against = b.passRelmse * b.sampleRays;
    if (!(product > 0) || !(against > 0) || !std::isfinite(product) || !std::isfinite(against)) return fallback;
    const double m = std::sqrt(product / against);
    return int(std::clamp(m, double(least), double(most)));
}

}  // namespace lucerna
