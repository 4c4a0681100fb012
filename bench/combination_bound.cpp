// How much a per-tile combination of two methods could take off the relmse of one scene (issue
// 38): the bound auto's combination works under. Each seed's renders of methods A and B (each
// with half the time of the single runs it is compared with) are combined per tile by inverse-
// error weights taken from the true errors (against the reference) of the other seeds' renders
// of the same methods, so that no weight sees the values it weighs. Also the combination by one
// weight for the whole image, to tell what the tiles add. Then the split of twice the time
// between A and B that the tiles' mean errors over all seeds predict best (a tile's error as
// 1 / time, each tile combined by its inverse errors), against all of it to A or to B.
//   bench_combination_bound REF.exr TILE A_1.exr B_1.exr A_2.exr B_2.exr ...   (at least 2 seeds)
// Prints per seed the relmse of A, B, the per-tile and the whole-image combination, their means
// over the seeds, and the predicted line.

#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"
#include "render/engine/measured_auto/film_measures.h"

#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

using namespace lucerna;

namespace {

// Per tile of auto's grid, the sum over its pixels and channels of SPEC's relmse terms,
// (x - ref)^2 / (ref^2 + 0.01), non-finite values left out (as compareImages).
std::vector<double> tileErrors(const Image& test, const Image& ref, const TileGrid& tiles) {
    if (test.width != ref.width || test.height != ref.height) throw std::runtime_error("an image differs in size from REF");
    std::vector<double> e(size_t(tiles.count()), 0.0);
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double r = ref.at(x, y)[c], d = double(test.at(x, y)[c]) - r;
                if (std::isfinite(d)) e[size_t(tiles.of(x, y))] += d * d / relmseDenominator(r);
            }
    return e;
}

// Each pixel wa * a + (1 - wa) * b, wa the weight of the pixel's tile (constant over the tile).
Image blend(const Image& a, const Image& b, const std::vector<double>& wa, const TileGrid& tiles) {
    Image out(a.width, a.height);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const float w = float(wa[size_t(tiles.of(x, y))]);
            out.at(x, y) = a.at(x, y) * w + b.at(x, y) * (1 - w);
        }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 7 || (argc - 3) % 2 != 0) {
        std::fprintf(stderr, "usage: bench_combination_bound REF.exr TILE A_1.exr B_1.exr A_2.exr B_2.exr ...\n");
        return 2;
    }
    try {
        const Image ref = readExr(argv[1]);
        const int size = std::stoi(argv[2]);
        if (size < 1) throw std::runtime_error("TILE must be at least 1");
        const TileGrid grid(ref.width, ref.height, size);
        std::vector<Image> a, b;
        for (int i = 3; i < argc; i += 2) a.push_back(readExr(argv[i])), b.push_back(readExr(argv[i + 1]));
        std::vector<std::vector<double>> ea, eb;
        for (size_t s = 0; s < a.size(); ++s) ea.push_back(tileErrors(a[s], ref, grid)), eb.push_back(tileErrors(b[s], ref, grid));
        const size_t tiles = size_t(grid.count());
        double sumA = 0, sumB = 0, sumTiles = 0, sumImage = 0;
        std::printf("%-6s %12s %12s %12s %12s\n", "seed", "A", "B", "per tile", "one weight");
        for (size_t s = 0; s < a.size(); ++s) {
            // The other seeds' errors, per tile and over the image.
            std::vector<double> otherA(tiles, 0.0), otherB(tiles, 0.0);
            double imageA = 0, imageB = 0;
            for (size_t o = 0; o < a.size(); ++o) {
                if (o == s) continue;
                for (size_t t = 0; t < tiles; ++t) otherA[t] += ea[o][t], otherB[t] += eb[o][t], imageA += ea[o][t], imageB += eb[o][t];
            }
            std::vector<double> wTiles(tiles), wImage(tiles, imageB / (imageA + imageB));
            for (size_t t = 0; t < tiles; ++t)
                wTiles[t] = otherA[t] + otherB[t] > 0 ? otherB[t] / (otherA[t] + otherB[t]) : 0.5;
            const double ra = compareImages(a[s], ref).relmse, rb = compareImages(b[s], ref).relmse;
            const double rt = compareImages(blend(a[s], b[s], wTiles, grid), ref).relmse;
            const double ri = compareImages(blend(a[s], b[s], wImage, grid), ref).relmse;
            std::printf("%-6zu %12.4g %12.4g %12.4g %12.4g\n", s + 1, ra, rb, rt, ri);
            sumA += ra, sumB += rb, sumTiles += rt, sumImage += ri;
        }
        const double n = double(a.size());
        std::printf("%-6s %12.4g %12.4g %12.4g %12.4g\n", "mean", sumA / n, sumB / n, sumTiles / n, sumImage / n);
        // Twice the time, share f to A: a tile's error e_A / (2 f) from A, e_B / (2 (1 - f))
        // from B, combined 1 / (2 f / e_A + 2 (1 - f) / e_B).
        std::vector<double> meanA(tiles, 0.0), meanB(tiles, 0.0);
        for (size_t s = 0; s < a.size(); ++s)
            for (size_t t = 0; t < tiles; ++t) meanA[t] += ea[s][t] / n, meanB[t] += eb[s][t] / n;
        const double values = 3.0 * double(ref.width) * double(ref.height);
        const auto predicted = [&](double f) {
            double sum = 0;
            for (size_t t = 0; t < tiles; ++t) {
                const double precision = (meanA[t] > 0 ? 2 * f / meanA[t] : 0) + (meanB[t] > 0 ? 2 * (1 - f) / meanB[t] : 0);
                sum += precision > 0 ? 1 / precision : 0;
            }
            return sum / values;
        };
        double bestShare = 0, best = predicted(0);
        for (int k = 1; k <= 100; ++k)
            if (const double e = predicted(k / 100.0); e < best) best = e, bestShare = k / 100.0;
        std::printf("twice the time, predicted: all to A %.4g, all to B %.4g, best split %.2f to A %.4g\n", predicted(1),
                    predicted(0), bestShare, best);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_combination_bound: %s\n", e.what());
        return 1;
    }
    return 0;
}
