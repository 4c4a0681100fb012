#include "core/image/image_metrics.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lucerna {

ImageMetrics compareImages(const Image& test, const Image& reference) {
    if (test.width != reference.width || test.height != reference.height)
        throw std::invalid_argument("image sizes differ: " + std::to_string(test.width) + "x" +
                                    std::to_string(test.height) + " against " +
                                    std::to_string(reference.width) + "x" + std::to_string(reference.height));
    ImageMetrics m;
    double se = 0, rel = 0, st = 0, sr = 0;
    for (size_t i = 0; i < test.pixels.size(); ++i) {
        const Rgb& t = test.pixels[i];
        const Rgb& r = reference.pixels[i];
        const bool tFinite = isFinite(t);
        if (!tFinite) ++m.nonfinite;
        if (!tFinite || !isFinite(r)) continue;
        ++m.includedPixels;
        for (int c = 0; c < 3; ++c) {
            const double d = double(t[c]) - double(r[c]);
            se += d * d;
            rel += d * d / (double(r[c]) * r[c] + 0.01);
            st += t[c];
            sr += r[c];
        }
    }
    const double n = 3.0 * double(m.includedPixels);
    if (n > 0) {
        m.rmse = std::sqrt(se / n);
        m.relmse = rel / n;
        m.meanTest = st / n;
        m.meanRef = sr / n;
    }
    return m;
}

std::string formatMetrics(const ImageMetrics& m) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "rmse: %.9g\nrelmse: %.9g\nmean_test: %.9g\nmean_ref: %.9g\nnonfinite: %ld\n",
                  m.rmse, m.relmse, m.meanTest, m.meanRef, m.nonfinite);
    return buf;
}

}  // namespace lucerna
