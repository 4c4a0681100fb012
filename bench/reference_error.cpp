// How far a reference image is from the truth, in SPEC's relmse, from independent renders of the
// same scene (issue 38): the reference's own error adds to every render's relmse against it, and
// pulls ratios of two methods' relmse toward 1. With renders A_i independent of each other and of
// the reference R, all unbiased, and SPEC's terms (x - y)^2 / (r^2 + 0.01) taken with R's r,
//   E rel(A_i, R) = e_i + c,   E rel(A_i, A_j) = e_i + e_j,
// so each pair gives c = (rel(A_i, R) + rel(A_j, R) - rel(A_i, A_j)) / 2 (three-cornered hat);
// printed: each render's relmse against R and the estimate of its own error e_i, and c, the mean
// over the pairs with the spread of the pairs' values.
//   bench_reference_error REF.exr A_1.exr A_2.exr [A_3.exr ...]

#include "core/image/exr_io.h"
#include "render/engine/measured_auto/film_measures.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <vector>

using namespace lucerna;

namespace {

// SPEC's relmse of a against b, each term divided by the reference's denominator (non-finite
// terms left out, as compareImages).
double relmse(const Image& a, const Image& b, const Image& ref) {
    double sum = 0;
    for (size_t p = 0; p < ref.pixels.size(); ++p)
        for (int c = 0; c < 3; ++c) {
            const double d = double(a.pixels[p][c]) - double(b.pixels[p][c]);
            if (std::isfinite(d)) sum += d * d / relmseDenominator(ref.pixels[p][c]);
        }
    return sum / (3.0 * double(ref.pixels.size()));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_reference_error REF.exr A_1.exr A_2.exr [A_3.exr ...]\n");
        return 2;
    }
    try {
        const Image ref = readExr(argv[1]);
        std::vector<Image> renders;
        for (int i = 2; i < argc; ++i) {
            renders.push_back(readExr(argv[i]));
            if (renders.back().width != ref.width || renders.back().height != ref.height)
                throw std::runtime_error(std::string(argv[i]) + " differs in size from REF");
        }
        const size_t n = renders.size();
        std::vector<double> toRef(n);
        for (size_t i = 0; i < n; ++i) toRef[i] = relmse(renders[i], ref, ref);
        std::vector<double> pairs;
        std::vector<std::vector<double>> between(n, std::vector<double>(n, 0.0));
        for (size_t i = 0; i < n; ++i)
            for (size_t j = i + 1; j < n; ++j) {
                between[i][j] = between[j][i] = relmse(renders[i], renders[j], ref);
                pairs.push_back(0.5 * (toRef[i] + toRef[j] - between[i][j]));
            }
        double c = 0;
        for (double x : pairs) c += x / double(pairs.size());
        double spread = 0;
        for (double x : pairs) spread += (x - c) * (x - c) / double(pairs.size());
        std::printf("%-40s %12s %12s\n", "render", "vs REF", "own error");
        for (size_t i = 0; i < n; ++i) std::printf("%-40s %12.4g %12.4g\n", argv[i + 2], toRef[i], toRef[i] - c);
        std::printf("reference's own error: %.4g (pairs: %zu, their spread %.2g)\n", c, pairs.size(), std::sqrt(spread));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_reference_error: %s\n", e.what());
        return 1;
    }
    return 0;
}
