#pragma once
// The lens sub-chain's kernel (cmlt_chain.h), on raster points alone so that a test can check
// its stationary density on a small target.
//
// A candidate is the current raster point plus a Gaussian of sigmaPixels, wrapped around the
// image (a torus: T(x, y) = T(y, x) everywhere, edges included). Of p candidates drawn from the
// same point, the chain takes one chosen uniformly and accepts it with min(1, f(y) / f(x)): a
// mixture of p identical Metropolis-Hastings kernels, so it keeps f's density.

#include "render/trace/rng.h"

#include <span>

namespace lucerna {

V2f perturbRaster(const V2f& x, float sigmaPixels, float width, float height, Rng& rng);

struct LensMove {
    int candidate = 0;
    bool accepted = false;
};
// currentF > 0.
LensMove chooseLensMove(std::span<const double> candidateF, double currentF, Rng& rng);

}  // namespace lucerna
