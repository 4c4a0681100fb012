// Prints the mean of each EXR's pixels (the mean of the three channels, as Image::mean), and with
// --expect V its relative error against V: the closed forms of the sphere family (bench/families.sh).
//   bench_image_mean [--expect V] FILE.exr...

#include "core/image/exr_io.h"

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    double expected = 0;
    int first = 1;
    if (argc > 2 && std::strcmp(argv[1], "--expect") == 0) {
        expected = std::stod(argv[2]);
        first = 3;
    }
    if (first >= argc) {
        std::fprintf(stderr, "usage: bench_image_mean [--expect V] FILE.exr...\n");
        return 2;
    }
    for (int i = first; i < argc; ++i) {
        try {
            const double mean = lucerna::readExr(argv[i]).mean();
            if (expected > 0) std::printf("%s mean %.6f error %+.3f%%\n", argv[i], mean, 100.0 * (mean / expected - 1.0));
            else std::printf("%s mean %.6f\n", argv[i], mean);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "bench_image_mean: %s: %s\n", argv[i], e.what());
            return 1;
        }
    }
    return 0;
}
