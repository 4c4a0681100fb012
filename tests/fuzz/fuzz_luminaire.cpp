// libFuzzer: IES and EULUMDAT text either parses into a distribution with finite flux and peak,
// or throws LuminaireFileError with one line; nothing else escapes, nothing crashes.

#include "core/photometry/eulumdat_file.h"
#include "core/photometry/ies_file.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {
void check(const lucerna::GoniometricDistribution& d) {
    if (!std::isfinite(d.integratedFlux()) || !std::isfinite(d.maxIntensity())) std::abort();
}
void checkMessage(const std::exception& e) {
    for (const char* c = e.what(); *c; ++c)
        if (static_cast<unsigned char>(*c) < 0x20) std::abort();  // one printable line
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        check(lucerna::parseIes(text, "fuzz.ies"));
    } catch (const lucerna::LuminaireFileError& e) {
        checkMessage(e);
    }
    try {
        check(lucerna::parseEulumdat(text, "fuzz.ldt"));
    } catch (const lucerna::LuminaireFileError& e) {
        checkMessage(e);
    }
    return 0;
}
