#include "render/backend/film.h"

#include <cmath>
#include <limits>

namespace lucerna {

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
    double sum = 0;
    size_t count = 0;
    for (size_t i = 0; i < sums_[0].size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double sa = scale_[0] * sums_[0][i][c], sb = scale_[1] * sums_[1][i][c];
            const double a = sa / samples_[0], b = sb / samples_[1];
            const double m = (sa + sb) / n;
            // With per-sample variance s^2, E[(a - b)^2] = s^2 (1/na + 1/nb) while the combined
            // mean has variance s^2 / n: the ratio is na nb / n^2 (1/4 for equal halves).
            const double mse = (a - b) * (a - b) * (samples_[0] / n) * (samples_[1] / n);
            if (std::isfinite(mse)) {
                sum += mse / (m * m + 0.01);
                ++count;
            }
        }
    return count ? sum / double(count) : 0.0;
}

}  // namespace lucerna
