#pragma once
// The pass loop, one for every caller (the command line, bench, grids, tests and the window's
// converging render): passes of a prepared backend until the sample count or the time budget is
// reached, or, open-ended, until the task is cancelled; held between passes while the caller
// says so; with progress and frames published on the way.

#include "core/task_system.h"
#include "render/backend/backend.h"

#include <functional>

namespace lucerna {

struct RenderFrame {
    Image image;                // the combined estimate, with header attributes
    double seconds = 0;         // rendering time so far (prepare excluded)
    double samplesPerPixel = 0;
    int passes = 0;
    double estimatedRelmse = 0; // from the film's half-buffers (NaN before two passes)
};

// The frame of a backend's film now: the combined image with SPEC.md's header attributes, the
// backend's diagnostics and its image layers (per-light layers).
RenderFrame makeRenderFrame(const Backend& backend, std::string_view backendName,
                            const RenderSettings& settings, double seconds, int passes);

// How the loop runs beyond the settings' spp and seconds.
struct PassLoopOptions {
    // A frame goes to `latest` after each of the first eagerPasses passes (the picture changes
    // most then), then at most every publishSeconds (0: after every pass), and at the end.
    double publishSeconds = 0.5;
    // ... and at least this share of the render time so far since the last frame (log-spaced
    // frames, for lucerna bench's log-spaced samples: a frame's cost is render time).
    double publishShare = 0;
    int eagerPasses = 0;
    // Until cancelled, whatever spp and seconds say (the window's converging render); no progress
    // is set and no final frame is made.
    bool openEnded = false;
    // While this returns true the loop holds between passes (a user's pause, the preview's claim
    // on the cores); held time is not render time.
    std::function<bool()> hold;
    // When this returns true the loop ends at the next pass boundary as if its budget were spent,
    // and makes its final frame of the passes done (the command line's --save-on-interrupt).
    std::function<bool()> finishEarly;
    // When set, frames made once four passes are done carry the albedo under each pixel
    // (kAlbedoLayer of render/trace/surface_layers.h), traced once from this scene at the film's
    // size, so that the lux view can divide by it (render/display/display.h, pixelIlluminance).
    SceneSnapshot albedoScene;
    // A share of a render run by several processes (a distributed render, pooled_films.h): of the
    // render's passes 0, 1, 2, ... (the settings' spp counts them all), this process runs those
    // whose index modulo shareCount is shareIndex. With globalPassIndices the backend gets those
    // indices, so that the processes' passes are disjoint passes of the one estimate a single
    // process would make (path, bdpt, ir, preview); without, it numbers its own passes 0, 1, ...
    // (the Metropolis backends: each process its own chains, from its own seed).
    int shareIndex = 0, shareCount = 1;
    bool globalPassIndices = true;
    // Called after each complete pass with the number of passes this process has done.
    std::function<void(int passes)> afterPass;
};

// Runs passes of a prepared backend. With neither spp nor seconds set, 64 passes (SPEC.md), of
// which a share (options.shareIndex) runs here.
// Render time is the wall-clock time since the call less the held time. Sets the context's
// progress. Returns the final frame (complete passes only; empty when open-ended).
RenderFrame runPasses(Backend& backend, std::string_view backendName, const RenderSettings& settings,
                           TaskContext& ctx, Latest<RenderFrame>* latest = nullptr, const PassLoopOptions& options = {});

}  // namespace lucerna
