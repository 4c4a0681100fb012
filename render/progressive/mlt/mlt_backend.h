#pragma once
// The scheduling part of the Metropolis light transport backends (mlt, and cmlt, which swaps in
// its own chains): primary-sample-space chains (Kelemen et al. 2002) over the bidirectional
// sampler of the bdpt backend.
//
// Each film half has its own bootstrap (b, the normalisation, from independent uniform samples)
// and its own chains, seeded by resampling the bootstrap samples in proportion to f, which
// removes start-up bias (Veach 1997, section 11.3.1): the halves are independent estimates and
// their difference an honest error estimate. b is refined by the chains' large steps and applied
// at read-out. A pass runs the half's chains in parallel, each for its share of
// mutationsPerPixel * W * H steps; their deposits are added in chain order, so a render is
// reproducible whatever the number of threads.

#include "render/backend/backend.h"
#include "render/progressive/mlt/mlt_settings.h"

#include <functional>
#include <map>

namespace lucerna {

class MltChain;
class RenderScene;

// Makes a chain whose first state replays the bootstrap sample of seed `bootstrapSeed`.
using ChainFactory = std::function<std::unique_ptr<MltChain>(const RenderScene& scene, uint64_t bootstrapSeed)>;

// A variant's diagnostics (EXR attributes without the "lucerna:" prefix) from its chains'
// variantCounts(), summed over every chain of both film halves.
using VariantDiagnostics = std::function<void(const std::map<std::string, long long>& counts,
                                              std::map<std::string, std::string>& diagnostics)>;

std::unique_ptr<Backend> makeMetropolisBackend(SceneSnapshot scene, const RenderSettings& settings,
                                                          const MltSettings& mlt, ChainFactory makeChain,
                                                          VariantDiagnostics variantDiagnostics = {});

std::unique_ptr<Backend> makeMltBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
