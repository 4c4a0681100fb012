#pragma once
// `--backend ir`: Keller's instant radiosity, progressive. Each pass draws a fresh, independent VPL
// set (light paths seeded by (seed, pass)) and gathers it at one jittered camera sample per pixel
// (vpl_gatherer.h: direct light by next-event estimation, VPLs with a clamped geometric term,
// the residual by short path-traced paths). The film averages the passes; even and odd passes
// use disjoint VPL sets, so the two half-buffers are independent.

#include "render/backend/backend.h"

namespace lucerna {

std::unique_ptr<Backend> makeIrBackend(SceneSnapshot scene, const RenderSettings& settings);

}  // namespace lucerna
