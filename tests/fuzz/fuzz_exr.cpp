// libFuzzer: readExr on any bytes either returns an image of the size its header states or
// throws ImageError with one line; what it allocates is bounded by what the file holds (run with
// -rss_limit_mb to see that).

#include "core/image/exr_io.h"
#include "fuzz_input_file.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = lucerna::fuzz::inputFile(data, size, "exr");
    try {
        const lucerna::Image image = lucerna::readExr(path);
        if (image.pixels.size() != size_t(image.width) * size_t(image.height)) std::abort();
    } catch (const lucerna::ImageError& e) {
        if (std::string(e.what()).find('\n') != std::string::npos) std::abort();
    }
    return 0;
}
