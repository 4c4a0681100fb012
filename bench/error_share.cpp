// Where an image's relmse sits (issue 38): the share of SPEC's relmse that its worst pixels carry,
// and, with OUT.exr, the map of each pixel's term (the sum over its channels of
// (x - ref)^2 / (ref^2 + 0.01)) to look at with `lucerna convert`. A method whose error is a few
// fireflies and one whose error is spread over the image call for different remedies. Also the
// relmse left once the test image is scaled to the reference's mean: a normalisation's error
// (mir's Pc) against the pixels' own noise.
//   bench_error_share TEST.exr REF.exr [OUT.exr]

#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"
#include "render/engine/measured_auto/film_measures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <numeric>
#include <stdexcept>
#include <vector>

using namespace lucerna;

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4) {
        std::fprintf(stderr, "usage: bench_error_share TEST.exr REF.exr [OUT.exr]\n");
        return 2;
    }
    try {
        const Image test = readExr(argv[1]), ref = readExr(argv[2]);
        if (test.width != ref.width || test.height != ref.height) throw std::runtime_error("the images differ in size");
        Image map(ref.width, ref.height);
        std::vector<double> terms;
        for (int y = 0; y < ref.height; ++y)
            for (int x = 0; x < ref.width; ++x) {
                double e = 0;
                for (int c = 0; c < 3; ++c) {
                    const double r = ref.at(x, y)[c], d = double(test.at(x, y)[c]) - r;
                    if (std::isfinite(d)) e += d * d / relmseDenominator(r);
                }
                map.at(x, y) = Rgb(float(e), float(e), float(e));
                terms.push_back(e);
            }
        std::ranges::sort(terms, std::greater<>());
        const double total = std::accumulate(terms.begin(), terms.end(), 0.0);
        std::printf("relmse %.4g (compare: %.4g)\n", total / (3.0 * double(terms.size())), compareImages(test, ref).relmse);
        for (double share : {0.001, 0.01, 0.1, 0.5}) {
            const size_t n = std::max<size_t>(1, size_t(share * double(terms.size())));
            const double part = std::accumulate(terms.begin(), terms.begin() + long(n), 0.0);
            std::printf("worst %5.1f%% of the pixels (%zu): %.1f%% of the relmse\n", 100 * share, n, total > 0 ? 100 * part / total : 0.0);
        }
        const double scale = test.mean() > 0 ? ref.mean() / test.mean() : 1.0;
        Image scaled = test;
        for (Rgb& p : scaled.pixels) p = p * float(scale);
        std::printf("scaled to the reference's mean (x %.5f): relmse %.4g\n", scale, compareImages(scaled, ref).relmse);
        if (argc == 4) writeExr(argv[3], map);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_error_share: %s\n", e.what());
        return 1;
    }
    return 0;
}
