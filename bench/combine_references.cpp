// Combines independent renders of one scene into a reference: each pixel the mean of the inputs
// weighted by the inverse of each input's estimated relmse (its `lucerna:estimated_relmse`
// header attribute, the noise its two film halves show), and prints the relmse between each pair
// of inputs, the cross-check that they converge to the same image. The output's own estimate,
// from the inputs', goes in its `lucerna:estimated_relmse`. Used for issue 21's door
// references (bdpt and cmlt, bench/families.sh).
//   bench_combine_references OUT.exr IN.exr IN.exr...

#include "core/image/exr_io.h"
#include "core/image/image_metrics.h"

#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

using namespace lucerna;

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_combine_references OUT.exr IN.exr IN.exr...\n");
        return 2;
    }
    try {
        std::vector<Image> in;
        std::vector<double> weight;
        for (int i = 2; i < argc; ++i) {
            in.push_back(readExr(argv[i]));
            const auto it = in.back().attributes.find("lucerna:estimated_relmse");
            if (it == in.back().attributes.end()) throw std::runtime_error(std::string(argv[i]) + " has no estimated relmse");
            const double e = std::stod(it->second);
            weight.push_back(1.0 / e);
            std::printf("%s: estimated relmse %.3g\n", argv[i], e);
            if (in.back().width != in[0].width || in.back().height != in[0].height)
                throw std::runtime_error(std::string(argv[i]) + " differs in size from " + argv[2]);
        }
        for (size_t a = 0; a < in.size(); ++a)
            for (size_t b = a + 1; b < in.size(); ++b)
                std::printf("relmse %s against %s: %.3g\n", argv[a + 2], argv[b + 2], compareImages(in[a], in[b]).relmse);
        double total = 0;
        for (double w : weight) total += w;
        Image out(in[0].width, in[0].height);
        for (size_t p = 0; p < out.pixelCount(); ++p) {
            V3d sum(0, 0, 0);
            for (size_t i = 0; i < in.size(); ++i)
                sum += V3d(in[i].pixels[p].x, in[i].pixels[p].y, in[i].pixels[p].z) * weight[i];
            sum /= total;
            out.pixels[p] = Rgb(float(sum.x), float(sum.y), float(sum.z));
        }
        out.attributes["lucerna:reference"] = "inverse-error weighted mean of " + std::to_string(in.size()) + " renders";
        // Of independent inputs weighted w_i = (1 / e_i) / sum_j (1 / e_j): sum_i w_i^2 e_i = 1 / sum_j (1 / e_j).
        out.attributes["lucerna:estimated_relmse"] = std::to_string(1.0 / total);
        writeExr(argv[1], out);
        std::printf("wrote %s\n", argv[1]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_combine_references: %s\n", e.what());
        return 1;
    }
    return 0;
}
