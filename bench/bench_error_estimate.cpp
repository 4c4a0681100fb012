// How well the film's own error estimate (Film::estimatedRelmse, from its two half-buffers)
// tracks the true relmse against a reference, pass count by pass count, over several seeds: the
// figures behind the estimator's choice (BENCHMARKS.md, "The estimated error (issue 25)").
//
//   bench_error_estimate SCENE.json REF.exr BACKEND SEEDS MAX_PASSES [WIDTH HEIGHT]
//
// prints, for pass counts 4, 8, 16, ... up to MAX_PASSES: the true relmse, the film's estimate
// and the alternatives compared (each averaged over the seeds), so that a change of estimator is
// decided on figures, not on one scene.

#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"
#include "core/scene/scene_io.h"
#include "core/task_system.h"
#include "render/backend/film.h"
#include "render/engine/backend_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace lucerna;

namespace {

// The alternatives to the film's estimate (the mean of the 24 pixels around each pixel for the
// reference), from the two half images a and b of equal sample counts: each pixel and channel's
// squared half difference / 4 (the combined image's squared error, in expectation) over a
// stand-in for the reference's r^2 + 0.01: the pixel's own mean (the estimate before issue 25),
// the smaller half, the median and the mean of its 8 neighbours.
enum Estimator { OwnMean, HalvesMin, NeighbourMedian, NeighbourMean, kEstimators };
const char* const kNames[kEstimators] = {"own_mean", "halves_min", "median_8", "mean_8"};

std::array<double, kEstimators> estimates(const Image& a, const Image& b) {
    const int w = a.width, h = a.height;
    std::vector<std::array<float, 3>> m(a.pixels.size());
    for (size_t i = 0; i < m.size(); ++i)
        for (int c = 0; c < 3; ++c) m[i][c] = 0.5f * (a.pixels[i][c] + b.pixels[i][c]);
    std::array<double, kEstimators> sum{};
    size_t count = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            for (int c = 0; c < 3; ++c) {
                const double d = a.pixels[i][c] - b.pixels[i][c];
                const double e = d * d / 4;
                if (!std::isfinite(e)) continue;
                float nbr[8];
                int n = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        if (!dx && !dy) continue;
                        const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, h - 1);
                        nbr[n++] = m[size_t(yy) * w + xx][c];
                    }
                std::sort(nbr, nbr + 8);
                const double median = 0.5 * (nbr[3] + nbr[4]);
                double mean = 0;
                for (float v : nbr) mean += v / 8.0;
                const double own = m[i][c];
                const double lo = std::min(a.pixels[i][c], b.pixels[i][c]);
                sum[OwnMean] += e / (own * own + 0.01);
                sum[HalvesMin] += e / (lo * lo + 0.01);
                sum[NeighbourMedian] += e / (median * median + 0.01);
                sum[NeighbourMean] += e / (mean * mean + 0.01);
                ++count;
            }
        }
    for (double& s : sum) s /= double(std::max<size_t>(count, 1));
    return sum;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 6 && argc != 8) {
        std::fprintf(stderr, "usage: bench_error_estimate SCENE.json REF.exr BACKEND SEEDS MAX_PASSES [WIDTH HEIGHT]\n");
        return 2;
    }
    const auto scene = std::make_shared<const Scene>(loadScene(argv[1]));
    const Image reference = readExr(argv[2]);
    const std::string backendName = argv[3];
    const int seeds = std::atoi(argv[4]), maxPasses = std::atoi(argv[5]);
    RenderSettings settings;
    if (argc == 8) {
        settings.width = std::atoi(argv[6]);
        settings.height = std::atoi(argv[7]);
    }
    const BackendInfo* info = findBackend(backendName);
    if (!info) {
        std::fprintf(stderr, "no backend %s\n", backendName.c_str());
        return 2;
    }
    std::vector<int> checkpoints;
    for (int p = 4; p <= maxPasses; p *= 2) checkpoints.push_back(p);
    // Per checkpoint: the true relmse, the film's own estimate, and each alternative, per seed.
    std::vector<std::vector<std::array<double, kEstimators + 2>>> rows(checkpoints.size());
    TaskSystem tasks(0);
    for (int seed = 1; seed <= seeds; ++seed) {
        settings.seed = uint64_t(seed);
        auto backend = info->make(scene, settings);
        auto job = tasks.submit([&](TaskContext& ctx) {
            backend->prepare(ctx);
            size_t next = 0;
            for (int pass = 0; pass < maxPasses && next < checkpoints.size(); ++pass) {
                backend->renderPass(ctx, pass);
                if (pass + 1 != checkpoints[next]) continue;
                const Film& film = backend->film();
                std::array<double, kEstimators + 2> row{};
                row[0] = compareImages(film.image(), reference).relmse;
                row[1] = film.estimatedRelmse();
                const auto alt = estimates(film.halfImage(0), film.halfImage(1));
                std::copy(alt.begin(), alt.end(), row.begin() + 2);
                rows[next++].push_back(row);
            }
        });
        job->wait();
        job->rethrowIfFailed();
    }
    std::printf("passes,true_relmse,film_estimate");
    for (const char* n : kNames) std::printf(",%s", n);
    std::printf("\n");
    for (size_t k = 0; k < checkpoints.size(); ++k) {
        std::array<double, kEstimators + 2> mean{};
        for (const auto& r : rows[k])
            for (size_t j = 0; j < mean.size(); ++j) mean[j] += r[j] / double(rows[k].size());
        std::printf("%d", checkpoints[k]);
        for (double v : mean) std::printf(",%.4g", v);
        std::printf("\n");
    }
    return 0;
}
