#include "render/progressive/mir/pc_balance.h"

#include <algorithm>
#include <cmath>

namespace lucerna {

int balancedPcSamples(const PcBalance& b, int least, int most, int fallback) {
    const double product = b.sensitivity * b.sampleRelativeVariance * b.passRays;
    const double against = b.passRelmse * b.sampleRays;
    if (!(product > 0) || !(against > 0) || !std::isfinite(product) || !std::isfinite(against)) return fallback;
    const double m = std::sqrt(product / against);
    return int(std::clamp(m, double(least), double(most)));
}

}  // namespace lucerna
