#include "core/image/image.h"

namespace lucerna {

double Image::mean() const {
    double sum = 0;
    for (const Rgb& p : pixels) sum += double(p.x) + double(p.y) + double(p.z);
    return pixels.empty() ? 0.0 : sum / (3.0 * double(pixels.size()));
}

Image Image::downsampled(int factor) const {
    Image out(width / factor, height / factor);
    const double norm = 1.0 / (double(factor) * factor);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            double r = 0, g = 0, b = 0;
            for (int j = 0; j < factor; ++j)
                for (int i = 0; i < factor; ++i) {
                    const Rgb& p = at(x * factor + i, y * factor + j);
                    r += p.x; g += p.y; b += p.z;
                }
            out.at(x, y) = Rgb(float(r * norm), float(g * norm), float(b * norm));
        }
    out.attributes = attributes;
    return out;
}

}  // namespace lucerna
