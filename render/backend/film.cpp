#include "render/backend/film.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lucerna {

namespace {
// The neighbourhood that stands in for the reference in estimatedRelmse: (2 kRadius + 1)^2 - 1
// pixels around each pixel.
constexpr int kRadius = 2;
}  // namespace

Film::Film(int width, int height) : width_(width), height_(height) {
    for (auto& s : sums_) s.assign(size_t(width) * height, {0.0, 0.0, 0.0});
}

Film Film::sum(std::span<const Film* const> films) {
    if (films.empty()) return Film(0, 0);
    Film out(films.front()->width_, films.front()->height_);
    out.samples_ = films.front()->samples_;
    for (int h = 0; h < 2; ++h) {
        if (out.samples_[h] <= 0) continue;
        for (const Film* f : films) {
            if (f->samples_[h] <= 0) continue;
            const double k = f->scale_[h] * out.samples_[h] / f->samples_[h];
            for (size_t i = 0; i < out.sums_[h].size(); ++i)
                for (int c = 0; c < 3; ++c) out.sums_[h][i][c] += k * f->sums_[h][i][c];
        }
    }
    return out;
}

void Film::rewriteAdditive(size_t blockSize, const std::function<void(std::span<double>)>& combine) {
    const size_t values = 3 * sums_[0].size(), total = 2 * values + 2;  // two halves, two counts
    const std::array<double, 2> scale = scale_;  // every block is read with the film's own scales
    const auto at = [&](size_t k) -> double& {
        if (k >= 2 * values) return samples_[k - 2 * values];
        const size_t h = k / values, i = k % values;
        return sums_[h][i / 3][i % 3];
    };
    std::vector<double> block;
    for (size_t begin = 0; begin < total; begin += std::max<size_t>(1, blockSize)) {
        const size_t n = std::min(std::max<size_t>(1, blockSize), total - begin);
        block.resize(n);
        for (size_t k = 0; k < n; ++k) {
            const size_t index = begin + k;
            block[k] = index < 2 * values ? scale[index / values] * at(index) : at(index);
        }
        combine(block);
        for (size_t k = 0; k < n; ++k) at(begin + k) = block[k];
    }
    scale_ = {1.0, 1.0};
}

Image Film::image() const {
    Image img(width_, height_);
    const double n = samplesPerPixel();
    if (n <= 0) return img;
    for (size_t i = 0; i < img.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) img.pixels[i][c] = float((scale_[0] * sums_[0][i][c] + scale_[1] * sums_[1][i][c]) / n);
    return img;
}

Image Film::halfImage(int half) const {
    Image img(width_, height_);
    const double n = samples_[half];
    if (n <= 0) return img;
    for (size_t i = 0; i < img.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) img.pixels[i][c] = float(scale_[half] * sums_[half][i][c] / n);
    return img;
}

double Film::estimatedRelmse() const {
    if (samples_[0] <= 0 || samples_[1] <= 0) return std::numeric_limits<double>::quiet_NaN();
    const double n = samplesPerPixel();
    std::vector<std::array<double, 3>> mean(sums_[0].size());
    for (size_t i = 0; i < mean.size(); ++i)
        for (int c = 0; c < 3; ++c) mean[i][c] = (scale_[0] * sums_[0][i][c] + scale_[1] * sums_[1][i][c]) / n;
    double sum = 0;
    size_t count = 0;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const size_t i = size_t(y) * width_ + x;
            // SPEC.md's relmse divides by the reference's r^2 + 0.01. The pixel's own mean cannot
            // stand in for r: a firefly inflates it exactly as much as the half difference, so a
            // pixel whose error is a thousand times r reports about 1. The mean of the 24 pixels
            // around it is independent of the pixel's own noise and, where the image is smooth at
            // that scale, estimates r; 8 neighbours read 1.4 to 4 times too high where a firefly
            // lands in one pixel of twenty (BENCHMARKS.md, "The estimated error (issue 25)").
            std::array<double, 3> local{0, 0, 0};
            int neighbours = 0;
            for (int dy = -kRadius; dy <= kRadius; ++dy)
                for (int dx = -kRadius; dx <= kRadius; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if ((!dx && !dy) || xx < 0 || yy < 0 || xx >= width_ || yy >= height_) continue;
                    for (int c = 0; c < 3; ++c) local[c] += mean[size_t(yy) * width_ + xx][c];
                    ++neighbours;
                }
            for (int c = 0; c < 3; ++c) {
                const double r = neighbours ? local[c] / neighbours : mean[i][c];
                const double a = scale_[0] * sums_[0][i][c] / samples_[0], b = scale_[1] * sums_[1][i][c] / samples_[1];
                // With per-sample variance s^2, E[(a - b)^2] = s^2 (1/na + 1/nb) while the combined
                // mean has variance s^2 / n: the ratio is na nb / n^2 (1/4 for equal halves).
                const double mse = (a - b) * (a - b) * (samples_[0] / n) * (samples_[1] / n);
                if (std::isfinite(mse) && std::isfinite(r)) {
                    sum += mse / (r * r + 0.01);
                    ++count;
                }
            }
        }
    return count ? sum / double(count) : 0.0;
}

}  // namespace lucerna
