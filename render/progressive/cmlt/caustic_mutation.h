#pragma once
// The caustic sub-chain's kernel (cmlt_chain.h), on the primary sample space sampler alone so
// that a test can check its stationary density on a small target.
//
// A candidate is a copy of the chain's sampler moved by a small step of the light stream alone
// (PssSampler::startStreamStep): every light number moves by a Gaussian, the camera and
// connection numbers stay, so with the camera subpath fixed the light subpath swings around it,
// Veach's caustic perturbation in primary sample space. Each candidate draws its own random
// numbers (its generator seeded from the chain's). Of p candidates the chain takes one chosen
// uniformly and accepts it with min(1, f(y) / f(x)) (chooseLensMove): a mixture of p identical
// symmetric Metropolis-Hastings kernels, so it keeps f's density. Numbers the current state has
// not read (f does not depend on them) are realised independently by each candidate, which is a
// Gibbs refresh of coordinates f ignores before each try: it keeps the density too.

#include "render/trace/pss_sampler.h"

#include <vector>

namespace lucerna {

class CausticTries {
public:
    // p candidates, copies of `from` each begun as a small step of the light stream with fresh
    // random numbers from `rng`. Evaluate each by reading its numbers; take one by assigning it
    // to the chain's sampler.
    void start(const PssSampler& from, int p, Rng& rng);
    PssSampler& candidate(int i) { return candidates_[size_t(i)]; }

private:
    std::vector<PssSampler> candidates_;  // kept between steps: copies reuse their capacity
};

}  // namespace lucerna
