#include "render/progressive/cmlt/caustic_mutation.h"

namespace lucerna {

void CausticTries::start(const PssSampler& from, int p, Rng& rng) {
    if (candidates_.size() < size_t(p)) candidates_.resize(size_t(p), from);
    for (int i = 0; i < p; ++i) {
        PssSampler& c = candidates_[size_t(i)];
        c = from;
        const uint64_t seed = (uint64_t(rng.nextUint()) << 32) | rng.nextUint();
        c.rng() = Rng(seed, uint64_t(i));
        c.startStreamStep(SampleStream::Light);
    }
}

}  // namespace lucerna
