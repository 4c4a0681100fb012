#pragma once
// The scheduling part of the mlt backend: Metropolis light transport in primary sample space
// (Kelemen et al. 2002) over the bidirectional sampler of the bdpt backend.
//
// Each film half has its own bootstrap (b, the normalisation, from independent uniform samples)
// and its own chains, seeded by resampling the bootstrap samples in proportion to f, which
// removes start-up bias (Veach 1997, section 11.3.1): the halves are independent estimates and
// their difference an honest error estimate. A pass runs the half's chains in parallel, each for
// its share of mutationsPerPixel * W * H steps; the chains' deposits are added in chain order, so
// a render is reproducible whatever the number of threads.

#include "render/progressive/backend.h"

namespace lucerna {

std::unique_ptr<ProgressiveBackend> makeMltBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
