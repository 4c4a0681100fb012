#include "render/progressive/backend.h"

#include "render/progressive/bdpt/bdpt_backend.h"
#include "render/progressive/cmlt/cmlt_backend.h"
#include "render/progressive/ir/ir_backend.h"
#include "render/progressive/mir/mir_backend.h"
#include "render/progressive/mlt/mlt_backend.h"
#include "render/progressive/path/path_backend.h"
#include "render/preview/preview_backend.h"

namespace lucerna {

namespace {
// The explicit factory table: one row per backend.
const BackendInfo kBackends[] = {
    {"path", "unidirectional path tracing with next-event estimation and MIS", &makePathBackend},
    {"bdpt", "bidirectional path tracing: every connection strategy, light-tracing splats, power-heuristic MIS", &makeBdptBackend},
    {"ir", "instant radiosity: fresh VPLs per pass, clamped gathering with path-traced bias compensation", &makeIrBackend},
    {"mir", "Metropolis instant radiosity: VPLs from a multiple-try Metropolis chain over camera-to-light paths", &makeMirBackend},
    {"mlt", "Metropolis light transport: primary-sample-space chains driving the bidirectional sampler", &makeMltBackend},
    {"cmlt", "coherent Metropolis light transport: MLT seeds, lens sub-chains of candidates traced as packets, expected-value deposits", &makeCmltBackend},
    {"preview", "interactive VPL preview (OpenGL through EGL): deferred shading, interleaved sampling, shadow-mapped direct light", &makePreviewBackend},
};
}  // namespace

std::span<const BackendInfo> backendTable() { return kBackends; }

const BackendInfo* findBackend(std::string_view name) {
    for (const BackendInfo& b : kBackends)
        if (b.name == name) return &b;
    return nullptr;
}

}  // namespace lucerna
