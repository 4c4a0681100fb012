#pragma once
// The scheduling shared by every progressive backend: passes until the sample count or the time
// budget is reached or the task is cancelled, with progress and frames published on the way.

#include "core/task_system.h"
#include "render/progressive/backend.h"

namespace lucerna {

struct RenderFrame {
    Image image;                // the combined estimate, with header attributes
    double seconds = 0;         // rendering time so far (prepare excluded)
    double samplesPerPixel = 0;
    int passes = 0;
    double estimatedRelmse = 0; // from the film's half-buffers (NaN before two passes)
};

// A number for an EXR header attribute or a diagnostic: %g with the given significant digits.
std::string formatNumber(double v, int significantDigits = 9);

// The frame of a backend's film now: the combined image with SPEC.md's header attributes, the
// backend's diagnostics and its image layers (per-light layers).
RenderFrame makeRenderFrame(const ProgressiveBackend& backend, std::string_view backendName,
                            const RenderSettings& settings, double seconds, int passes);

// Runs passes of a prepared backend. With neither spp nor seconds set, 64 passes (SPEC.md).
// Publishes a frame to `latest` (if given) at most every publishSeconds and at the end; sets the
// context's progress. Returns the final frame (complete passes only).
RenderFrame runProgressive(ProgressiveBackend& backend, std::string_view backendName, const RenderSettings& settings,
                           TaskContext& ctx, Latest<RenderFrame>* latest = nullptr, double publishSeconds = 0.5);

}  // namespace lucerna
