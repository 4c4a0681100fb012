#pragma once
// The cmlt backend: the Metropolis scheduler of mlt (mlt_backend.h) with coherent lens
// sub-chains (cmlt_chain.h).

#include "render/backend/backend.h"

namespace lucerna {

std::unique_ptr<Backend> makeCmltBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
